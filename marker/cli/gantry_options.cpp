#include "marker/cli/gantry_options.hpp"

#include <cstdio>
#include <string>

namespace mark::cli {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

void add_gantry_options(CLI::App& app, GantryArgs& a) {
  const GantryConfig d;
  const std::string g = "Gantry";
  app.add_option("--steps-per-mm", a.steps_per_mm,
                 "motor steps per mm, both axes (default " + num(d.x.steps_per_mm) + ")")
      ->group(g);
  app.add_option("--x-steps-per-mm", a.x_steps_per_mm, "motor steps per mm, X axis")->group(g);
  app.add_option("--y-steps-per-mm", a.y_steps_per_mm, "motor steps per mm, Y axis")->group(g);
  app.add_option("--speed", a.speed_mm_s,
                 "top speed, both axes, mm/s (default " + num(d.x.max_speed_mm_s) + ")")
      ->group(g);
  app.add_option("--x-speed", a.x_speed_mm_s, "top speed, X axis, mm/s")->group(g);
  app.add_option("--y-speed", a.y_speed_mm_s, "top speed, Y axis, mm/s")->group(g);
  app.add_option("--accel", a.accel_mm_s2,
                 "acceleration, both axes, mm/s² (default " + num(d.x.accel_mm_s2) + ")")
      ->group(g);
  app.add_option("--x-accel", a.x_accel_mm_s2, "acceleration, X axis, mm/s²")->group(g);
  app.add_option("--y-accel", a.y_accel_mm_s2, "acceleration, Y axis, mm/s²")->group(g);
  app.add_option("--strike-ms", a.strike_ms,
                 "time per needle strike, ms (default " + num(d.strike_s * 1000) + ")")
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
