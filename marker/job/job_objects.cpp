// The object kinds a job file can hold, one parser each, looked up by "kind". A new kind adds
// its body type to ObjectBody (job_file.hpp), a parse function here and a row in kKinds.
#include <cmath>

#include "fonts/error.hpp"
#include "marker/job/job_file.hpp"
#include "marker/job/job_parse_context.hpp"
#include "marker/job/json_reader.hpp"

namespace mark {
namespace {

constexpr double kBig = 1e6;

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
  l.height_mm = o.number("height_mm", 1e-3, 1000, "mm").value_or(l.height_mm);
  l.width_factor = o.number("width_factor", 0.01, 100).value_or(l.width_factor);
  l.gap_mm = o.number("gap_mm", -kBig, kBig, "mm").value_or(l.gap_mm);
  l.line_spacing = o.number("line_spacing", 0.01, 100).value_or(l.line_spacing);
  if (auto a = o.choice("align", {"left", "center", "right"}))
    l.align = *a == "center" ? Align::center : *a == "right" ? Align::right : Align::left;
  l.base = Point(o.number("x_mm", -kBig, kBig, "mm").value_or(0),
                 o.number("y_mm", -kBig, kBig, "mm").value_or(0));
  l.angle_deg = o.number("angle_deg", -360, 360, "°").value_or(0);
  l.italic_deg = o.number("italic_deg", -79.9, 79.9, "°").value_or(0);
  l.mirror = o.boolean("mirror").value_or(false);
  l.replace_missing = o.boolean("replace_missing").value_or(false);
  if (o.has("circle")) {
    JsonReader c = o.object("circle");
    CircleFit fit;
    const auto r = c.number("radius_mm", 1e-3, kBig, "mm");
    if (!r) c.fail("radius_mm", "circular fitting needs the circle's radius");
    fit.radius_mm = *r;
    fit.center = Point(c.number("cx_mm", -kBig, kBig, "mm").value_or(0),
                       c.number("cy_mm", -kBig, kBig, "mm").value_or(0));
    fit.start_angle_deg = c.number("start_angle_deg", -360, 360, "°");
    fit.inside = c.boolean("inside").value_or(false);
    c.finish();
    if (l.angle_deg != 0)
      o.fail("angle_deg", "a text angle cannot be combined with circular fitting; use circle.start_angle_deg");
    l.circle = fit;
  }
  if (auto s = o.choice("order", {"glyph", "shortest"})) t.order = parse_stroke_order(*s);
  return t;
}

struct Kind {
  const char* name;
  ObjectBody (*parse)(JsonReader&, const JobParseContext&);
};

constexpr Kind kKinds[] = {{"text", parse_text}};

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
