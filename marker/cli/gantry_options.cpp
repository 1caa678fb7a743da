#include "marker/cli/gantry_options.hpp"

#include <utility>

#include "marker/cli/option_ranges.hpp"
#include "marker/limits/peen_settings.hpp"

namespace mark::cli {

void add_gantry_options(CLI::App& app, GantryArgs& a) {
  for (auto [setting, value] : {std::pair{&kStepsPerMm, &a.steps_per_mm}, {&kXStepsPerMm, &a.x_steps_per_mm},
                                {&kYStepsPerMm, &a.y_steps_per_mm}, {&kGantrySpeed, &a.speed_mm_s},
                                {&kXSpeed, &a.x_speed_mm_s}, {&kYSpeed, &a.y_speed_mm_s},
                                {&kGantryAccel, &a.accel_mm_s2}, {&kXAccel, &a.x_accel_mm_s2},
                                {&kYAccel, &a.y_accel_mm_s2}, {&kStrike, &a.strike_ms}})
    add_setting(app, *setting, *value)->group("Gantry");
}

GantryConfig to_gantry(const GantryArgs& a) {
  GantryConfig g;
  auto set = [](double& x, double& y, const std::optional<double>& both,
                const std::optional<double>& only_x, const std::optional<double>& only_y) {
    if (both) x = y = *both;
    if (only_x) x = *only_x;
    if (only_y) y = *only_y;
  };
  set(g.x.steps_per_mm, g.y.steps_per_mm, a.steps_per_mm, a.x_steps_per_mm, a.y_steps_per_mm);
  set(g.x.max_speed_mm_s, g.y.max_speed_mm_s, a.speed_mm_s, a.x_speed_mm_s, a.y_speed_mm_s);
  set(g.x.accel_mm_s2, g.y.accel_mm_s2, a.accel_mm_s2, a.x_accel_mm_s2, a.y_accel_mm_s2);
  if (a.strike_ms) g.strike_s = *a.strike_ms / 1000.0;
  g.validate();
  return g;
}

}  // namespace mark::cli
