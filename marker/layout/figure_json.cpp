#include "marker/layout/figure_json.hpp"

#include <numbers>

#include "fonts/overloaded.hpp"
#include "fonts/utf8.hpp"

namespace mark {
namespace {

nlohmann::json xy(const Point& p) { return nlohmann::json::array({p.x(), p.y()}); }
double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

}  // namespace

nlohmann::json element_to_json(const Element& e) {
  nlohmann::json j;
  j["laser"] = e.laser();
  j["start"] = xy(e.start());
  j["end"] = xy(e.end());
  std::visit(Overloaded{[&](const Line&) { j["kind"] = "line"; },
                        [&](const CircularArc& a) {
                          j["kind"] = "arc";
                          j["center"] = xy(a.center);
                          j["radius"] = a.radius;
                          j["ccw"] = a.sweep > 0;
                        },
                        [&](const EllipticalArc& el) {
                          j["kind"] = "ellipse";
                          j["center"] = xy(el.center);
                          j["rx"] = el.rx;
                          j["ry"] = el.ry;
                          j["rotation_deg"] = degrees(el.rotation);
                          j["start_deg"] = degrees(el.start_param);
                          j["end_deg"] = degrees(el.start_param + el.sweep);
                          j["ccw"] = el.sweep > 0;
                        }},
             e.geometry());
  return j;
}

nlohmann::json box_json(const Box& b) {
  if (b.empty()) return nullptr;
  return {{"x_min", b.min.x()}, {"y_min", b.min.y()}, {"x_max", b.max.x()}, {"y_max", b.max.y()}};
}

nlohmann::json figure_to_json(const Figure& figure) {
  nlohmann::json glyphs = nlohmann::json::array();
  for (const PlacedGlyph& g : figure.glyphs) {
    nlohmann::json elements = nlohmann::json::array();
    for (const Element& e : g.elements) elements.push_back(element_to_json(e));
    glyphs.push_back({{"char", encode_utf8(g.code_point)},
                      {"line", g.line},
                      {"origin", xy(g.origin)},
                      {"rotation_deg", degrees(g.rotation_rad)},
                      {"elements", std::move(elements)}});
  }
  const Box b = figure.bounds();
  nlohmann::json out = {{"glyphs", std::move(glyphs)}};
  if (!b.empty()) out["bounds_mm"] = box_json(b);
  return out;
}

}  // namespace mark
