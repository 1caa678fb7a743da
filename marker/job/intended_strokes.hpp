#pragma once
// What the marks should look like, for the quality figures: every lit stroke of the Figure as a
// densely sampled polyline (consecutive points ≤ step apart; a closed stroke ends on its first
// point). Sampled from the exact elements, not from the planner's commands, so the planner's
// blanking lines and delays are judged against the figure itself.
#include <vector>

#include "driver/vec2.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

std::vector<std::vector<Vec2>> intended_polylines(const Figure& figure, double step_mm = 0.002);

}  // namespace mark
