#include "marker/job/head_pen.hpp"

#include "marker/limits/pen_settings.hpp"
#include "marker/plan/input_shaper.hpp"

namespace mark {

Range head_speed_range(const Quantity& speed, const HeadModel& head) {
  return limited_range(speed, head.max_speed_mm_s, "head " + head.name + "'s positioning limit");
}

Range head_tick_range(const HeadModel& head) {
  return limited_range(kTick, head.max_tick_s() * 1e6, "20 % of head " + head.name + "'s τ");
}

HeadDynamics dynamics_of(const HeadProfile& profile) {
  return {profile.lag_s(), profile.inertia_s2(), profile.max_accel_mm_s2};
}

Pen pen_for_profile(const HeadProfile& profile, CornerStrategy strategy, double mark_speed_mm_s,
                    double tick_s, const PenRules& rules) {
  Pen pen = default_pen(strategy, dynamics_of(profile), mark_speed_mm_s,
                        kJumpSpeedShare * profile.max_speed_mm_s, tick_s, rules);
  // A resonance the identification saw: the look-ahead planner shapes against it, where the
  // tick can place the shaper's impulses (at most a quarter of the tick rate).
  if ((rules.lookahead || rules.feed_forward) && profile.resonance_hz > 0 && profile.resonance_hz <= max_shaper_hz(tick_s)) {
    pen.shaper_hz = profile.resonance_hz;
    pen.shaper_zeta = profile.resonance_zeta;
  }
  return pen;
}

Pen pen_for_head(const HeadModel& head, CornerStrategy strategy, double mark_speed_mm_s,
                 double tick_s, const PenRules& rules) {
  return pen_for_profile(datasheet_profile(head), strategy, mark_speed_mm_s, tick_s, rules);
}

}  // namespace mark
