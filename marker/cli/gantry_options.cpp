#include "marker/cli/gantry_options.hpp"

#include <string>

#include "marker/cli/option_ranges.hpp"

namespace mark::cli {
namespace {

// Pin markers run 20–200 steps per mm, 50–300 mm/s and 1–10 m/s²; the ranges leave room on both
// sides without letting a number reach where the time model stops meaning anything.
const Range kStepsRange{1, 10000, "steps/mm"};
const Range kSpeedRange{1, 5000, "mm/s"};
const Range kAccelRange{10, 100000, "mm/s²"};
const Range kStrikeRange{0, 1000, "ms"};

}  // namespace

void add_gantry_options(CLI::App& app, GantryArgs& a) {
  const GantryConfig d;
  const std::string g = "Gantry";
  add_ranged_option(app, "--steps-per-mm", a.steps_per_mm,
                    "motor steps per mm, both axes (default " + format_number(d.x.steps_per_mm) + ")",
                    kStepsRange)
      ->group(g);
  add_ranged_option(app, "--x-steps-per-mm", a.x_steps_per_mm, "motor steps per mm, X axis", kStepsRange)->group(g);
  add_ranged_option(app, "--y-steps-per-mm", a.y_steps_per_mm, "motor steps per mm, Y axis", kStepsRange)->group(g);
  add_ranged_option(app, "--speed", a.speed_mm_s,
                    "top speed, both axes, mm/s (default " + format_number(d.x.max_speed_mm_s) + ")", kSpeedRange)
      ->group(g);
  add_ranged_option(app, "--x-speed", a.x_speed_mm_s, "top speed, X axis, mm/s", kSpeedRange)->group(g);
  add_ranged_option(app, "--y-speed", a.y_speed_mm_s, "top speed, Y axis, mm/s", kSpeedRange)->group(g);
  add_ranged_option(app, "--accel", a.accel_mm_s2,
                    "acceleration, both axes, mm/s² (default " + format_number(d.x.accel_mm_s2) + ")",
                    kAccelRange)
      ->group(g);
  add_ranged_option(app, "--x-accel", a.x_accel_mm_s2, "acceleration, X axis, mm/s²", kAccelRange)->group(g);
  add_ranged_option(app, "--y-accel", a.y_accel_mm_s2, "acceleration, Y axis, mm/s²", kAccelRange)->group(g);
  add_ranged_option(app, "--strike-ms", a.strike_ms,
                    "time per needle strike, ms (default " + format_number(d.strike_s * 1000) + ")", kStrikeRange)
      ->group(g);
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
