#include "marker/peen/gantry.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

#include "base/error.hpp"

namespace mark {
namespace {

void require_positive(double v, const char* name) {
  if (!(v > 0) || !std::isfinite(v))
    throw InputError(std::string("gantry ") + name + " = " + std::to_string(v) +
                     ": must be a positive number");
}

double steps_to_mm(std::int64_t steps, const AxisLimits& axis) {
  return static_cast<double>(std::llabs(steps)) / axis.steps_per_mm;
}

}  // namespace

void GantryConfig::validate() const {
  require_positive(x.steps_per_mm, "x steps per mm");
  require_positive(x.max_speed_mm_s, "x max speed (mm/s)");
  require_positive(x.accel_mm_s2, "x acceleration (mm/s²)");
  require_positive(y.steps_per_mm, "y steps per mm");
  require_positive(y.max_speed_mm_s, "y max speed (mm/s)");
  require_positive(y.accel_mm_s2, "y acceleration (mm/s²)");
  if (!(strike_s >= 0) || !std::isfinite(strike_s))
    throw InputError("gantry strike time = " + std::to_string(strike_s) +
                     " s: must be zero or a positive number");
}

StepPoint to_steps(const Point& mm, const GantryConfig& gantry) {
  return {std::llround(mm.x() * gantry.x.steps_per_mm), std::llround(mm.y() * gantry.y.steps_per_mm)};
}

Point to_mm(const StepPoint& s, const GantryConfig& gantry) {
  return {static_cast<double>(s.x) / gantry.x.steps_per_mm,
          static_cast<double>(s.y) / gantry.y.steps_per_mm};
}

AxisProfile axis_profile(std::int64_t steps, const AxisLimits& axis) {
  AxisProfile p;
  p.steps = steps;
  p.distance_mm = steps_to_mm(steps, axis);
  if (steps == 0) return p;
  const double v = axis.max_speed_mm_s, a = axis.accel_mm_s2, d = p.distance_mm;
  if (d >= v * v / a) {
    // Trapezoid: v/a to reach top speed (covering v²/2a), the same to stop, cruise in between.
    p.peak_speed_mm_s = v;
    p.accel_s = v / a;
    p.cruise_s = (d - v * v / a) / v;
  } else {
    // Triangle: half the distance accelerating, half decelerating.
    p.accel_s = std::sqrt(d / a);
    p.peak_speed_mm_s = a * p.accel_s;
  }
  return p;
}

double axis_time_s(double d, const AxisLimits& axis) {
  const double v = axis.max_speed_mm_s, a = axis.accel_mm_s2;
  if (d <= 0) return 0;
  return d >= v * v / a ? d / v + v / a : 2 * std::sqrt(d / a);
}

double move_time_s(const StepPoint& from, const StepPoint& to, const GantryConfig& g) {
  const double tx = axis_time_s(steps_to_mm(to.x - from.x, g.x), g.x);
  const double ty = axis_time_s(steps_to_mm(to.y - from.y, g.y), g.y);
  return tx > ty ? tx : ty;
}

}  // namespace mark
