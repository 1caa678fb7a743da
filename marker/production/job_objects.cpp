// The object kinds a job file can hold, one parser each, looked up by "kind". A new kind adds
// its body type to ObjectBody (job_file.hpp), a parse function here and a row in kKinds.
#include <cmath>

#include "base/error.hpp"
#include "marker/codes/symbology.hpp"
#include "marker/limits/code_limits.hpp"
#include "marker/limits/fill_limits.hpp"
#include "marker/limits/layout_limits.hpp"
#include "marker/production/job_file.hpp"
#include "marker/production/job_parse_context.hpp"
#include "marker/production/json_reader.hpp"

namespace mark {
namespace {

// A fill ("fill" of a text object, "hatch" of a code): hatch sets, direction, order, inset,
// contour passes; insets default to the job's spot radius. `with_rule`: the fill rule is asked
// too (text; a code's modules never overlap).
FillOptions parse_fill(JsonReader& f, const JobParseContext& ctx, bool with_rule) {
  FillOptions o;
  const double radius_mm = ctx.spot_diameter_um / 2000;
  o.inset_mm = o.contour_inset_mm = radius_mm;
  if (with_rule)
    if (auto r = f.choice("rule", {"nonzero", "evenodd"})) o.rule = parse_fill_rule(*r);
  if (const nlohmann::json* sets = f.raw("sets")) {
    if (!sets->is_array() || sets->empty() || sets->size() > 8)
      f.fail("sets", "expected a list of 1 to 8 hatch sets {\"angle_deg\": …, \"spacing_mm\": …}");
    o.sets.clear();
    for (std::size_t i = 0; i < sets->size(); ++i) {
      JsonReader s((*sets)[i], f.file(), json_index(f.path_of("sets"), i));
      HatchSet h;
      h.angle_deg = s.number("angle_deg", kHatchAngleRange).value_or(h.angle_deg);
      h.spacing_mm = s.number("spacing_mm", kHatchSpacingRange).value_or(h.spacing_mm);
      s.finish();
      o.sets.push_back(h);
    }
  } else {
    o.sets.front().angle_deg = f.number("angle_deg", kHatchAngleRange).value_or(0);
    o.sets.front().spacing_mm = f.number("spacing_mm", kHatchSpacingRange).value_or(o.sets.front().spacing_mm);
  }
  if (auto d = f.choice("direction", {"bidirectional", "unidirectional"})) o.direction = parse_hatch_direction(*d);
  if (auto d = f.choice("order", {"short", "raster"})) o.order = parse_hatch_order(*d);
  o.inset_mm = f.number("inset_mm", kFillInsetRange).value_or(o.inset_mm);
  o.contour_passes = static_cast<int>(f.integer("contour_passes", kContourPassesRange).value_or(0));
  if (auto p = f.choice("contour_placement", {"before", "after"})) o.contour_placement = parse_contour_placement(*p);
  o.contour_inset_mm = f.number("contour_inset_mm", kFillInsetRange).value_or(o.contour_inset_mm);
  o.contour_spacing_mm = f.number("contour_spacing_mm", kHatchSpacingRange).value_or(o.sets.front().spacing_mm);
  f.finish();
  return o;
}

ObjectBody parse_text(JsonReader& o, const JobParseContext& ctx) {
  TextObject t;
  const std::optional<std::string> source = o.string("template");
  if (!source) o.fail("template", "a text object needs a template (the text to mark, fields in braces)");
  t.text = TextTemplate::parse(*source, ctx.file + ": " + o.path_of("template"));
  if (auto f = o.string("font")) {
    if (f->empty()) o.fail("font", "the font name is empty");
    t.font = *f;
  }
  LayoutOptions& l = t.layout;
  l.height_mm = o.number("height_mm", kHeightRange).value_or(l.height_mm);
  l.width_factor = o.number("width_factor", kWidthFactorRange).value_or(l.width_factor);
  l.gap_mm = o.number("gap_mm", kGapRange).value_or(l.gap_mm);
  l.line_spacing = o.number("line_spacing", kLineSpacingRange).value_or(l.line_spacing);
  if (auto a = o.choice("align", {"left", "center", "right"}))
    l.align = *a == "center" ? Align::center : *a == "right" ? Align::right : Align::left;
  l.base = Point(o.number("x_mm", kPositionRange).value_or(0),
                 o.number("y_mm", kPositionRange).value_or(0));
  l.angle_deg = o.number("angle_deg", kAngleRange).value_or(0);
  l.italic_deg = o.number("italic_deg", kItalicRange).value_or(0);
  l.mirror = o.boolean("mirror").value_or(false);
  l.replace_missing = o.boolean("replace_missing").value_or(false);
  if (o.has("circle")) {
    JsonReader c = o.object("circle");
    CircleFit fit;
    const auto r = c.number("radius_mm", kRadiusRange);
    if (!r) c.fail("radius_mm", "circular fitting needs the circle's radius");
    fit.radius_mm = *r;
    fit.center = Point(c.number("cx_mm", kPositionRange).value_or(0),
                       c.number("cy_mm", kPositionRange).value_or(0));
    fit.start_angle_deg = c.number("start_angle_deg", kAngleRange);
    fit.inside = c.boolean("inside").value_or(false);
    c.finish();
    if (l.angle_deg != 0)
      o.fail("angle_deg", "a text angle cannot be combined with circular fitting; use circle.start_angle_deg");
    l.circle = fit;
  }
  if (auto s = o.choice("order", {"glyph", "shortest"})) t.order = parse_stroke_order(*s);
  if (o.has("fill")) {
    JsonReader f = o.object("fill");
    t.fill = parse_fill(f, ctx, true);
  }
  return t;
}

// Runs a parser of ours that throws InputError and reports it at the key.
template <class F>
auto at_key(JsonReader& o, std::string_view key, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    o.fail(key, e.what());
  }
}

ObjectBody parse_code(JsonReader& o, const JobParseContext& ctx) {
  CodeJobObject c;
  std::vector<std::string> names;
  for (std::string_view n : symbology_names()) names.emplace_back(n);
  const std::optional<std::string> symbology = o.choice("symbology", names);
  if (!symbology) o.fail("symbology", "a code object needs its symbology (" + names.front() + ", …)");
  c.code.spec.symbology = parse_symbology(*symbology);
  const std::optional<std::string> source = o.string("template");
  if (!source) o.fail("template", "a code object needs a template (the data, fields in braces)");
  c.data = TextTemplate::parse(*source, ctx.file + ": " + o.path_of("template"));
  c.escapes = o.boolean("escapes").value_or(false);
  CodeSpec& s = c.code.spec;
  if (auto m = o.string("matrix_size"))
    at_key(o, "matrix_size", [&] { parse_matrix_size(*m, s.matrix_rows, s.matrix_cols); });
  if (auto sh = o.choice("shape", {"square", "rectangular", "any"})) s.shape = parse_matrix_shape(*sh);
  if (auto e = o.choice("qr_ecc", {"L", "M", "Q", "H"})) s.qr_ecc = e->front();
  s.qr_version = static_cast<int>(o.integer("qr_version", kQrVersionRange).value_or(0));
  CodeLayout& l = c.code.layout;
  l.center = Point(o.number("x_mm", kCodePositionRange).value_or(0), o.number("y_mm", kCodePositionRange).value_or(0));
  l.angle_deg = o.number("angle_deg", kCodeAngleRange).value_or(0);
  l.size_mm = o.number("size_mm", kCodeSizeRange).value_or(0);
  l.module_mm = o.number("module_mm", kModuleRange).value_or(0);
  if (l.size_mm > 0 && l.module_mm > 0) o.fail("module_mm", "give size_mm or module_mm, not both");
  l.bar_height_mm = o.number("bar_height_mm", kBarHeightRange).value_or(0);
  if (auto st = o.choice("style", {"square", "dot", "line"})) l.style = parse_module_style(*st);
  if (auto d = o.choice("dot", {"spiral", "circle"})) l.dot = parse_dot_shape(*d);
  l.dot_share = o.number("dot_size", kDotShareRange).value_or(1.0);
  l.invert = o.boolean("invert").value_or(false);
  if (o.has("hatch")) {
    JsonReader h = o.object("hatch");
    l.fill = parse_fill(h, ctx, false);
  } else {
    l.fill.inset_mm = l.fill.contour_inset_mm = ctx.spot_diameter_um / 2000;
  }
  return c;
}

struct Kind {
  const char* name;
  ObjectBody (*parse)(JsonReader&, const JobParseContext&);
};

constexpr Kind kKinds[] = {{"text", parse_text}, {"code", parse_code}};

}  // namespace

ObjectBody parse_object_body(const std::string& kind, JsonReader& object, const JobParseContext& ctx) {
  for (const Kind& k : kKinds)
    if (kind == k.name) return k.parse(object, ctx);
  std::string names;
  for (const Kind& k : kKinds) names += (names.empty() ? "" : ", ") + std::string(k.name);
  object.fail("kind", "\"" + kind + "\" is not an object kind (" + names + ")");
}

std::vector<std::string> object_kind_names() {
  std::vector<std::string> n;
  for (const Kind& k : kKinds) n.emplace_back(k.name);
  return n;
}

}  // namespace mark
