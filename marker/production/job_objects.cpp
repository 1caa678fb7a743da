// The object kinds a job file can hold, one parser each, looked up by "kind". A new kind adds
// its body type to ObjectBody (job_file.hpp), a parse function here and a row in kKinds.
#include <cmath>

#include "base/error.hpp"
#include "marker/codes/iso_grade.hpp"
#include "marker/codes/symbology.hpp"
#include "marker/limits/code_settings.hpp"
#include "marker/limits/fill_settings.hpp"
#include "marker/limits/layout_settings.hpp"
#include "marker/limits/production_settings.hpp"
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
    if (auto r = f.choice(kFillRule)) o.rule = parse_fill_rule(*r);
  if (const nlohmann::json* sets = f.raw("sets")) {
    if (!sets->is_array() || !kHatchSetsRange.contains(static_cast<std::int64_t>(sets->size())))
      f.fail("sets", "expected a list of " + kHatchSetsRange.text() +
                         " hatch sets {\"angle_deg\": …, \"spacing_mm\": …}");
    o.sets.clear();
    for (std::size_t i = 0; i < sets->size(); ++i) {
      JsonReader s((*sets)[i], f.file(), json_index(f.path_of("sets"), i));
      HatchSet h;
      h.angle_deg = s.number(kHatchAngle).value_or(h.angle_deg);
      h.spacing_mm = s.number(kHatchSpacing).value_or(h.spacing_mm);
      s.finish();
      o.sets.push_back(h);
    }
  } else {
    o.sets.front().angle_deg = f.number_or_default(kHatchAngle);
    o.sets.front().spacing_mm = f.number_or_default(kHatchSpacing);
  }
  if (auto d = f.choice(kHatchDirection)) o.direction = parse_hatch_direction(*d);
  if (auto d = f.choice(kHatchOrder)) o.order = parse_hatch_order(*d);
  o.inset_mm = f.number(kHatchInset).value_or(o.inset_mm);
  o.contour_passes = static_cast<int>(f.integer(kContourPasses).value_or(kContourPasses.fallback()));
  if (auto p = f.choice(kContourPlacement)) o.contour_placement = parse_contour_placement(*p);
  o.contour_inset_mm = f.number(kContourInset).value_or(o.contour_inset_mm);
  o.contour_spacing_mm = f.number(kContourSpacing).value_or(o.sets.front().spacing_mm);
  f.finish();
  return o;
}

ObjectBody parse_text(JsonReader& o, const JobParseContext& ctx) {
  TextObject t;
  const std::optional<std::string> source = o.string(kTemplate);
  if (!source) o.fail(kTemplate.name.key, "a text object needs a template (the text to mark, fields in braces)");
  t.text = TextTemplate::parse(*source, ctx.file + ": " + o.path_of(kTemplate.name.key));
  if (auto f = o.string(kFont)) {
    if (f->empty()) o.fail(kFont.name.key, "the font name is empty");
    t.font = *f;
  }
  LayoutOptions& l = t.layout;
  l.height_mm = o.number_or_default(kHeight);
  l.width_factor = o.number_or_default(kWidthFactor);
  l.gap_mm = o.number_or_default(kGap);
  l.line_spacing = o.number_or_default(kLineSpacing);
  const std::string align = o.choice(kAlign).value_or(std::string(kAlign.value));
  l.align = align == "center" ? Align::center : align == "right" ? Align::right : Align::left;
  l.base = Point(o.number_or_default(kX), o.number_or_default(kY));
  l.angle_deg = o.number_or_default(kAngle);
  l.italic_deg = o.number_or_default(kItalic);
  l.mirror = o.boolean(kMirror).value_or(false);
  l.replace_missing = o.boolean(kReplaceMissing).value_or(false);
  if (o.has(kCircle.name.key)) {
    JsonReader c = o.object(kCircle.name.key);
    CircleFit fit;
    const auto r = c.number(kCircleRadius);
    if (!r) c.fail("radius_mm", "circular fitting needs the circle's radius");
    fit.radius_mm = *r;
    fit.center = Point(c.number_or_default(kCircleX), c.number_or_default(kCircleY));
    fit.start_angle_deg = c.number(kStartAngle);
    fit.inside = c.boolean(kInside).value_or(false);
    c.finish();
    if (l.angle_deg != 0)
      o.fail(kAngle.name.key, "a text angle cannot be combined with circular fitting; use circle.start_angle_deg");
    l.circle = fit;
  }
  if (auto s = o.choice(kOrder)) t.order = parse_stroke_order(*s);
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
  const std::optional<std::string> source = o.string(kTemplate);
  if (!source) o.fail(kTemplate.name.key, "a code object needs a template (the data, fields in braces)");
  c.data = TextTemplate::parse(*source, ctx.file + ": " + o.path_of(kTemplate.name.key));
  c.escapes = o.boolean(kCodeEscapes).value_or(false);
  CodeSpec& s = c.code.spec;
  if (auto m = o.string(kMatrixSize))
    at_key(o, kMatrixSize.name.key, [&] { parse_matrix_size(*m, s.matrix_rows, s.matrix_cols); });
  if (auto sh = o.choice(kMatrixShape)) s.shape = parse_matrix_shape(*sh);
  if (auto e = o.choice(kQrEcc)) s.qr_ecc = e->front();
  s.qr_version = static_cast<int>(o.integer(kQrVersion).value_or(kQrVersion.fallback()));
  CodeLayout& l = c.code.layout;
  l.center = Point(o.number_or_default(kCodeX), o.number_or_default(kCodeY));
  l.angle_deg = o.number_or_default(kCodeAngle);
  // 0: not given (the layout then takes the other, or the default module).
  l.size_mm = o.number(kCodeSize).value_or(0);
  l.module_mm = o.number(kModule).value_or(0);
  if (l.size_mm > 0 && l.module_mm > 0) o.fail(kModule.name.key, "give size_mm or module_mm, not both");
  l.bar_height_mm = o.number(kBarHeight).value_or(0);
  if (auto st = o.choice(kModuleStyle)) l.style = parse_module_style(*st);
  if (auto d = o.choice(kDotShape)) l.dot = parse_dot_shape(*d);
  l.dot_share = o.number_or_default(kDotSize);
  l.invert = o.boolean(kCodeInvert).value_or(false);
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

MarkRequirement parse_requirement(JsonReader& object, bool is_code) {
  MarkRequirement r;
  if (!object.has("require")) return r;
  JsonReader q = object.object("require");
  if (auto c = q.choice(kRequireQuality)) r.quality = parse_quality_class(*c);
  if (auto g = q.choice(kRequireGrade)) {
    if (!is_code) q.fail("code_grade", "a text object carries no code to grade");
    r.code_grade = parse_grade(g->front());
  }
  q.choice(kRequireCode);  // "read": what every code must do anyway
  q.finish();
  return r;
}

std::vector<std::string> object_kind_names() {
  std::vector<std::string> n;
  for (const Kind& k : kKinds) n.emplace_back(k.name);
  return n;
}

}  // namespace mark
