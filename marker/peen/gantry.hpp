#pragma once
// The simulated X–Y stepper gantry of a pin marker. Each axis runs its own trapezoidal profile
// (accelerate at the axis' limit, cruise at its top speed if the move is long enough, decelerate);
// both axes start together and a move ends when the slower axis arrives. Positions are whole
// motor steps. The needle strikes only while the head stands still, for strike_s per dot.
#include <cstdint>

#include "fonts/box.hpp"

namespace mark {

struct AxisLimits {
  double steps_per_mm = 40.0;      // 0.025 mm per step
  double max_speed_mm_s = 150.0;
  double accel_mm_s2 = 3000.0;
};

struct GantryConfig {
  AxisLimits x;
  AxisLimits y;
  double strike_s = 0.005;  // one needle impact and rebound (about 200 strikes per second)

  // Throws InputError naming the first parameter that is not a positive finite number.
  void validate() const;
};

// A position in whole motor steps.
struct StepPoint {
  std::int64_t x = 0;
  std::int64_t y = 0;
  bool operator==(const StepPoint&) const = default;
};

StepPoint to_steps(const Point& mm, const GantryConfig& gantry);
Point to_mm(const StepPoint& steps, const GantryConfig& gantry);

// One axis' motion for one move: accelerate for accel_s to peak_speed, cruise for cruise_s,
// decelerate for accel_s. A move too short to reach the top speed is a triangle (cruise_s = 0).
struct AxisProfile {
  std::int64_t steps = 0;  // signed
  double distance_mm = 0;  // unsigned
  double peak_speed_mm_s = 0;
  double accel_s = 0;
  double cruise_s = 0;
  double duration_s() const { return 2 * accel_s + cruise_s; }
};

AxisProfile axis_profile(std::int64_t steps, const AxisLimits& axis);
// Duration of a move of `distance_mm` (≥ 0) on one axis: d/v + v/a when the axis reaches its top
// speed (d ≥ v²/a), 2·√(d/a) otherwise.
double axis_time_s(double distance_mm, const AxisLimits& axis);
// Duration of the move between two step positions: the slower axis' time.
double move_time_s(const StepPoint& from, const StepPoint& to, const GantryConfig& gantry);

}  // namespace mark
