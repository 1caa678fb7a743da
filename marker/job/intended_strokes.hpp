#pragma once
// What the marks should look like, for the quality figures: every lit stroke of the Figure as a
// polyline (a straight element one segment, a curve in pieces ≤ max(step, 5 µm), the quality
// reference's own sample step, so every element is sampled alike; a closed stroke ends on its
// first point). Sampled from the exact elements, not from the planner's commands, so the planner's
// blanking lines and delays are judged against the figure itself.
#include <vector>

#include "driver/vec2.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

std::vector<std::vector<Vec2>> intended_polylines(const Figure& figure, double step_mm = 0.002);

}  // namespace mark
