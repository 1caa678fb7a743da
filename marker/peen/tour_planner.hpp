#pragma once
// Our planner: the order of strikes that minimises the gantry's move time, found as a travelling
// salesman tour from home through every dot and back, with the trapezoidal move time (the slower
// axis of each move) as the edge cost. Any direction of travel, any order across characters.
#include "marker/peen/dot_text.hpp"
#include "marker/peen/gantry.hpp"
#include "marker/peen/peen_plan.hpp"
#include "marker/peen/tour_search.hpp"

namespace mark {

PeenPlan plan_optimized(const DotText& text, const Point& home_mm, const GantryConfig& gantry,
                        const TourOptions& options = {});

}  // namespace mark
