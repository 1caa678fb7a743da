#include "marker/peen/peen_json.hpp"

namespace mark {

nlohmann::json run_to_json(const PeenPlan& plan, const DotText& text, const GantryReport& run) {
  const double chars = static_cast<double>(std::max<std::size_t>(text.characters, 1));
  return {{"planner", plan.planner},
          {"dots", text.dots.size()},
          {"characters", text.characters},
          {"time_s", run.total_s},
          {"time_per_char_s", run.total_s / chars},
          {"travel_mm", run.travel_mm},
          {"reversals", run.reversals},
          {"moves", run.moves},
          {"strikes", run.strikes},
          {"move_time_s", run.move_s},
          {"strike_time_s", run.strike_s}};
}

nlohmann::json gantry_to_json(const GantryConfig& g) {
  return {{"steps_per_mm", {{"x", g.x.steps_per_mm}, {"y", g.y.steps_per_mm}}},
          {"max_speed_mm_s", {{"x", g.x.max_speed_mm_s}, {"y", g.y.max_speed_mm_s}}},
          {"accel_mm_s2", {{"x", g.x.accel_mm_s2}, {"y", g.y.accel_mm_s2}}},
          {"strike_s", g.strike_s}};
}

}  // namespace mark
