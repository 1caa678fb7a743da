#pragma once
// The JSON a planner's run reports: what `marker peen --json` prints.
#include <nlohmann/json.hpp>

#include "marker/peen/dot_text.hpp"
#include "marker/peen/gantry_run.hpp"
#include "marker/peen/peen_plan.hpp"

namespace mark {

// {planner, dots, characters, time_s, time_per_char_s, travel_mm, reversals, moves, strikes,
//  move_time_s, strike_time_s}
nlohmann::json run_to_json(const PeenPlan& plan, const DotText& text, const GantryReport& run);
// {steps_per_mm: {x, y}, max_speed_mm_s: {x, y}, accel_mm_s2: {x, y}, strike_s}
nlohmann::json gantry_to_json(const GantryConfig& gantry);

}  // namespace mark
