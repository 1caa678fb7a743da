#include "marker/job/job_checks.hpp"

#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "marker/layout/layout.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/limits/value_range.hpp"
#include "marker/plan/input_shaper.hpp"

namespace mark {
namespace {

std::string num(double v, int precision = 1) {
  std::ostringstream s;
  s.precision(precision);
  s << std::fixed << v;
  return s.str();
}

void check_speed(double speed_mm_s, const char* what, const HeadModel& head) {
  if (!(speed_mm_s > 0) || !std::isfinite(speed_mm_s) || speed_mm_s > head.max_speed_mm_s)
    throw InputError(std::string(what) + " " + num(speed_mm_s) + " mm/s is outside head " +
                     head.name + "'s limits (above 0, at most " + num(head.max_speed_mm_s, 0) +
                     " mm/s)");
}

}  // namespace

void check_pen(const Pen& pen, const HeadModel& head) {
  check_speed(pen.mark_speed_mm_s, "marking speed", head);
  check_speed(pen.jump_speed_mm_s, "jump speed", head);
  if (pen.join_speed_mm_s != 0) check_speed(pen.join_speed_mm_s, "blanking join speed", head);
  if (!(pen.tick_s >= kMinTick_s) || !(pen.tick_s <= head.max_tick_s()))
    throw InputError("tick " + num(pen.tick_s * 1e6, 2) + " µs is outside head " + head.name +
                     "'s limits (" + num(kMinTick_s * 1e6, 0) + " to " +
                     num(head.max_tick_s() * 1e6, 1) + " µs, 20 % of its tracking error)");
  for (double d : {pen.laser_on_delay_s, pen.laser_off_delay_s, pen.jump_delay_s,
                   pen.mark_delay_s, pen.polygon_delay_s, pen.run_in_mm.value_or(0),
                   pen.min_run_in_mm, pen.run_out_mm, pen.settle_mm})
    if (!(d >= 0) || !std::isfinite(d))
      throw InputError("pen delays and extension lengths must be finite and not negative");
  if (pen.lookahead || pen.feed_forward()) {
    struct Rate {
      double value;
      const char* what;
    };
    for (const Rate& r : {Rate{pen.accel_mm_s2, "look-ahead acceleration"},
                          Rate{pen.jump_accel_mm_s2, "look-ahead jump acceleration"},
                          Rate{pen.curve_accel_mm_s2, "look-ahead curve acceleration"}})
      if (!(r.value > 0) || !(r.value <= head.max_accel_mm_s2))
        throw InputError(std::string(r.what) + " " + num(r.value, 0) + " mm/s² is outside head " +
                         head.name + "'s limits (above 0, at most " +
                         num(head.max_accel_mm_s2, 0) + " mm/s²)");
    for (double d : {pen.junction_dv_mm_s, pen.laser_switch_speed_mm_s, pen.min_lit_speed_mm_s,
                     pen.accel_limit_mm_s2, pen.ff_lag_s, pen.ff_inertia_s2})
      if (!(d >= 0) || !std::isfinite(d))
        throw InputError("look-ahead and feed-forward parameters must be finite and not negative");
  }
  if (pen.shaper_hz != 0) {
    const double most = max_shaper_hz(pen.tick_s);
    if (!(pen.lookahead || pen.feed_forward()))
      throw InputError("--shaper-hz needs the look-ahead planner (give --lookahead or --feed-forward)");
    if (!(pen.shaper_hz > 0) || !(pen.shaper_hz <= most * (1 + 1e-9)))
      throw InputError("--shaper-hz " + num(pen.shaper_hz, 0) + " Hz is outside the range at a " +
                       num(pen.tick_s * 1e6, 1) + " µs tick (above 0, at most " + num(most, 0) +
                       " Hz, a quarter of the tick rate)");
    const Bounds zeta = kShaperZeta.bounds;
    if (!(pen.shaper_zeta >= zeta.min) || !(pen.shaper_zeta <= zeta.max))
      throw InputError("--shaper-zeta " + num(pen.shaper_zeta, 3) + " is outside " + num(zeta.min, 0) + " to " +
                       num(zeta.max, 1));
  }
}

void check_plan(const Plan& plan, const HeadModel& head) {
  check_pen(plan.pen, head);
  if (plan.strokes == 0) throw InputError("the text has nothing to mark (no lit strokes)");
  require_inside(plan.bounds(), Field{head.field_mm},
                 plan.pen.corner == CornerStrategy::blanking
                     ? "the job (figure plus blanking lines)"
                     : "the job (figure plus jumps)");
}

void check_field(const HeadModel& head, const DeviceDescription& device) {
  if (head.field_mm > device.field_mm * (1 + 1e-12))
    throw InputError("the job's field, " + format_number(head.field_mm) + " mm (--field, a job's field_mm), is larger than the " +
                     format_number(device.field_mm) + " mm field of device " + device.name + "; give at most " +
                     format_number(device.field_mm));
}

}  // namespace mark
