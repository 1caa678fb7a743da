#include "marker/plan/pen.hpp"

#include <cmath>
#include <string>

#include "base/error.hpp"

namespace mark {

std::string_view to_string(CornerStrategy strategy) {
  switch (strategy) {
    case CornerStrategy::blanking: return "blanking";
    case CornerStrategy::delays: return "delays";
    case CornerStrategy::none: return "none";
  }
  return "?";
}

CornerStrategy parse_corner_strategy(std::string_view name) {
  for (CornerStrategy s : {CornerStrategy::blanking, CornerStrategy::delays, CornerStrategy::none})
    if (name == to_string(s)) return s;
  throw InputError("corner strategy '" + std::string(name) +
                   "' is not one of blanking, delays, none");
}

std::uint32_t Pen::ticks(double seconds) const {
  return seconds <= 0 ? 0u : static_cast<std::uint32_t>(std::lround(seconds / tick_s));
}

Pen default_pen(CornerStrategy strategy, const HeadDynamics& head, double mark_speed_mm_s,
                double jump_speed_mm_s, double tick_s, const PenRules& rules) {
  Pen pen;
  pen.mark_speed_mm_s = mark_speed_mm_s;
  pen.jump_speed_mm_s = jump_speed_mm_s;
  pen.tick_s = tick_s;
  pen.corner = strategy;
  pen.lookahead = rules.lookahead || rules.feed_forward;
  if (pen.lookahead) {
    pen.accel_mm_s2 = rules.accel_share * head.max_accel_mm_s2;
    pen.jump_accel_mm_s2 = rules.jump_accel_share * head.max_accel_mm_s2;
    pen.curve_accel_mm_s2 = rules.curve_accel_share * head.max_accel_mm_s2;
    pen.junction_dv_mm_s = rules.junction_dv_mm_s;
    pen.accel_limit_mm_s2 = head.max_accel_mm_s2;
    pen.min_lit_speed_mm_s = rules.min_lit_speed_share * mark_speed_mm_s;
  }
  if (rules.feed_forward) {
    pen.ff_lag_s = head.lag_s;
    pen.ff_inertia_s2 = head.inertia_s2;
  }
  // The lag the delays and extensions wait for: none left once it is fed forward.
  const double tau = rules.feed_forward ? 0.0 : head.lag_s;
  switch (strategy) {
    case CornerStrategy::blanking:
      // The seed's delay means: the laser bit leaves τ after the coordinates, so at constant
      // speed it switches exactly when the lagging beam crosses the element's end points.
      pen.laser_on_delay_s = tau;
      pen.laser_off_delay_s = tau;
      pen.blank_angle_deg = rules.blank_angle_deg;
      if (rules.feed_forward) {
        // Extensions to reach and leave the marking speed: v²/(2a) at the lit rate.
        const double reach = pen.accel_mm_s2 > 0
                                 ? mark_speed_mm_s * mark_speed_mm_s / (2 * pen.accel_mm_s2)
                                 : 0.0;
        pen.run_in_mm = rules.run_in.value_or(rules.min_run_in) * reach;
        pen.run_out_mm = rules.run_out * reach;
        pen.settle_mm = rules.settle_um * 1e-3;
      } else {
        if (rules.run_in) pen.run_in_mm = *rules.run_in * mark_speed_mm_s * tau;
        pen.min_run_in_mm = rules.min_run_in * mark_speed_mm_s * tau;
        pen.run_out_mm = rules.run_out * mark_speed_mm_s * tau;
        pen.settle_mm = rules.settle_um * 1e-3;
        pen.tracking_error_s = tau;
      }
      pen.join_speed_mm_s = jump_speed_mm_s;
      break;
    case CornerStrategy::delays:
      pen.laser_on_delay_s = rules.laser_on * tau;
      pen.laser_off_delay_s = rules.laser_off * tau;
      pen.jump_delay_s = rules.jump * tau;
      pen.mark_delay_s = rules.mark * tau;
      pen.polygon_delay_s = rules.polygon * tau;
      pen.jump_settle_mm = rules.jump_settle_um * 1e-3;
      pen.tracking_error_s = tau;
      break;
    case CornerStrategy::none:
      break;
  }
  return pen;
}

Pen default_pen(CornerStrategy strategy, double tracking_error_s, double mark_speed_mm_s,
                double jump_speed_mm_s, double tick_s, const PenRules& rules) {
  PenRules r = rules;
  r.lookahead = r.feed_forward = false;
  return default_pen(strategy, HeadDynamics{tracking_error_s, 0, 0}, mark_speed_mm_s,
                     jump_speed_mm_s, tick_s, r);
}

}  // namespace mark
