#pragma once
// The Figure as JSON for other tools: {"glyphs": [{"char": "D", "elements": [...]}]}; each
// element has kind (line | arc | ellipse), laser, start and end ([x, y] mm); arcs add center,
// radius, ccw; ellipse arcs add center, rx, ry, rotation_deg, start_param, end_param, ccw
// (parameters in degrees).
#include <nlohmann/json.hpp>

#include "marker/layout/figure.hpp"

namespace mark {

nlohmann::json element_to_json(const Element& element);
// A box as every JSON output names one ("bounds_mm", "cut_bounds_mm", …): {"x_min", "y_min",
// "x_max", "y_max"} in mm; null for an empty box.
nlohmann::json box_json(const Box& box);
nlohmann::json figure_to_json(const Figure& figure);

}  // namespace mark
