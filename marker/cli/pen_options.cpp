#include "marker/cli/pen_options.hpp"

#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/cli/unread_options.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/plan/input_shaper.hpp"

namespace mark::cli {

void add_pen_options(CLI::App& app, PenArgs& a, bool with_speed) {
  add_setting(app, kCorner, a.corner);
  // The speeds and the tick are checked against the head in make_pen.
  if (with_speed) add_head_limited_setting(app, kMarkSpeed, a.speed_mm_s);
  add_head_limited_setting(app, kJumpSpeed, a.jump_speed_mm_s);
  add_head_limited_setting(app, kTick, a.tick_us);
  add_setting(app, kHeadProfile, a.head_profile);
  add_setting(app, kLookahead, a.lookahead);
  add_setting(app, kFeedForward, a.feed_forward);
  auto opt = [&](const Quantity& s, std::optional<double>& v) {
    add_setting(app, s, v)->group("Pen parameters (override the defaults)");
  };
  opt(kLaserOnDelay, a.laser_on_delay_us);
  opt(kLaserOffDelay, a.laser_off_delay_us);
  opt(kJumpDelay, a.jump_delay_us);
  opt(kJumpSettle, a.jump_settle_um);
  opt(kMarkDelay, a.mark_delay_us);
  opt(kPolygonDelay, a.polygon_delay_us);
  opt(kBlankAngle, a.blank_angle_deg);
  opt(kRunIn, a.run_in_mm);
  opt(kMinRunIn, a.min_run_in_mm);
  opt(kRunOut, a.run_out_mm);
  opt(kSettle, a.settle_um);
  add_head_limited_setting(app, kJoinSpeed, a.join_speed_mm_s)->group("Pen parameters (override the defaults)");
  opt(kTrackingError, a.tracking_error_us);
  opt(kAccel, a.accel_mm_s2);
  opt(kJumpAccel, a.jump_accel_mm_s2);
  opt(kCurveAccel, a.curve_accel_mm_s2);
  opt(kAccelLimit, a.accel_limit_mm_s2);
  opt(kJunctionDv, a.junction_dv_mm_s);
  opt(kLaserSwitchSpeed, a.laser_switch_speed_mm_s);
  opt(kMinLitSpeed, a.min_lit_speed_mm_s);
  opt(kFfLag, a.ff_lag_us);
  opt(kFfInertia, a.ff_inertia_us2);
  opt(kShaperHz, a.shaper_hz);
  opt(kShaperZeta, a.shaper_zeta);
  add_setting(app, kShaper, a.shaper)->group("Pen parameters (override the defaults)");
}

void add_laser_options(CLI::App& app, LaserSettings& laser) {
  add_setting(app, kPower, laser.power_pct);
  add_setting(app, kFrequency, laser.frequency_khz);
  add_setting(app, kPulseWidth, laser.pulse_width_ns);
}

HeadProfile planner_profile(const PenArgs& a, const HeadModel& head) {
  if (a.head_profile.empty()) return datasheet_profile(head);
  HeadProfile p = load_head_profile(a.head_profile);
  // A profile identifies one head: planning another head with it marks badly without a word.
  if (!p.head.empty() && p.head != head.name)
    throw InputError("--head-profile " + a.head_profile + ": identified on head " + p.head +
                     ", but the head is " + head.name + " (identify this head: marker head identify --head " +
                     head.name + ")");
  return p;
}

bool feeds_forward(const PenArgs& a) {
  return a.feed_forward || a.ff_lag_us.value_or(0) > 0 || a.ff_inertia_us2.value_or(0) > 0;
}

void refuse_unread_pen_options(const CLI::App& app, const PenArgs& a) {
  const bool lookahead = a.lookahead || feeds_forward(a);
  refuse_unread(app, kPenSettingList, [&](const SettingRef& s) { return pen_setting_unread(s, a.corner, lookahead); });
}

Pen make_pen(const PenArgs& a, const HeadModel& head) {
  // The other options' ranges were checked while parsing; these depend on the head and are
  // checked here only, with the ranges a job file's pen is checked with.
  check_range(kMarkSpeed.name.flag, a.speed_mm_s, head_speed_range(kMarkSpeed, head));
  if (a.jump_speed_mm_s) check_range(kJumpSpeed.name.flag, *a.jump_speed_mm_s, head_speed_range(kJumpSpeed, head));
  if (a.join_speed_mm_s) check_range(kJoinSpeed.name.flag, *a.join_speed_mm_s, head_speed_range(kJoinSpeed, head));
  check_range(kTick.name.flag, a.tick_us, head_tick_range(head));
  PenRules rules;
  rules.lookahead = a.lookahead;
  rules.feed_forward = feeds_forward(a);
  Pen pen = pen_for_profile(planner_profile(a, head), parse_corner_strategy(a.corner),
                            a.speed_mm_s, a.tick_us * 1e-6, rules);
  if (a.jump_speed_mm_s) {
    pen.jump_speed_mm_s = *a.jump_speed_mm_s;
    if (pen.corner == CornerStrategy::blanking) pen.join_speed_mm_s = pen.jump_speed_mm_s;
  }
  auto set = [](const std::optional<double>& v, double& field, double scale) {
    if (v) field = *v * scale;
  };
  set(a.laser_on_delay_us, pen.laser_on_delay_s, 1e-6);
  set(a.laser_off_delay_us, pen.laser_off_delay_s, 1e-6);
  set(a.jump_delay_us, pen.jump_delay_s, 1e-6);
  set(a.jump_settle_um, pen.jump_settle_mm, 1e-3);
  set(a.mark_delay_us, pen.mark_delay_s, 1e-6);
  set(a.polygon_delay_us, pen.polygon_delay_s, 1e-6);
  set(a.blank_angle_deg, pen.blank_angle_deg, 1);
  if (a.run_in_mm) pen.run_in_mm = *a.run_in_mm;
  set(a.min_run_in_mm, pen.min_run_in_mm, 1);
  set(a.run_out_mm, pen.run_out_mm, 1);
  set(a.settle_um, pen.settle_mm, 1e-3);
  set(a.join_speed_mm_s, pen.join_speed_mm_s, 1);
  set(a.tracking_error_us, pen.tracking_error_s, 1e-6);
  set(a.accel_mm_s2, pen.accel_mm_s2, 1);
  set(a.jump_accel_mm_s2, pen.jump_accel_mm_s2, 1);
  set(a.curve_accel_mm_s2, pen.curve_accel_mm_s2, 1);
  set(a.accel_limit_mm_s2, pen.accel_limit_mm_s2, 1);
  set(a.junction_dv_mm_s, pen.junction_dv_mm_s, 1);
  set(a.laser_switch_speed_mm_s, pen.laser_switch_speed_mm_s, 1);
  set(a.min_lit_speed_mm_s, pen.min_lit_speed_mm_s, 1);
  set(a.ff_lag_us, pen.ff_lag_s, 1e-6);
  set(a.ff_inertia_us2, pen.ff_inertia_s2, 1e-12);
  set(a.shaper_hz, pen.shaper_hz, 1);
  pen.shaper_zeta = a.shaper_zeta.value_or(*kShaperZeta.value);
  pen.shaper = parse_shaper_kind(a.shaper);
  return pen;
}

std::string pen_args_string(const Pen& p) {
  std::ostringstream s;
  const auto arg = [&](const auto& setting, double v) { s << " " << setting.name.flag << " " << exact_number(v); };
  s << kCorner.name.flag << " " << to_string(p.corner);
  arg(kMarkSpeed, p.mark_speed_mm_s);
  arg(kJumpSpeed, p.jump_speed_mm_s);
  arg(kTick, p.tick_s * 1e6);
  arg(kLaserOnDelay, p.laser_on_delay_s * 1e6);
  arg(kLaserOffDelay, p.laser_off_delay_s * 1e6);
  if (!pen_setting_unread(&kTrackingError, to_string(p.corner), true)) arg(kTrackingError, p.tracking_error_s * 1e6);
  switch (p.corner) {
    case CornerStrategy::delays:
      arg(kJumpDelay, p.jump_delay_s * 1e6);
      arg(kJumpSettle, p.jump_settle_mm * 1e3);
      arg(kMarkDelay, p.mark_delay_s * 1e6);
      arg(kPolygonDelay, p.polygon_delay_s * 1e6);
      break;
    case CornerStrategy::blanking:
      arg(kBlankAngle, p.blank_angle_deg);
      if (p.run_in_mm) arg(kRunIn, *p.run_in_mm);
      arg(kMinRunIn, p.min_run_in_mm);
      arg(kRunOut, p.run_out_mm);
      arg(kSettle, p.settle_mm * 1e3);
      arg(kJoinSpeed, p.join_speed_mm_s);
      break;
    case CornerStrategy::none: break;
  }
  if (p.lookahead || p.feed_forward()) {
    s << " " << kLookahead.name.flag;
    arg(kAccel, p.accel_mm_s2);
    arg(kJumpAccel, p.jump_accel_mm_s2);
    arg(kCurveAccel, p.curve_accel_mm_s2);
    arg(kAccelLimit, p.accel_limit_mm_s2);
    arg(kJunctionDv, p.junction_dv_mm_s);
    arg(kLaserSwitchSpeed, p.laser_switch_speed_mm_s);
    arg(kMinLitSpeed, p.min_lit_speed_mm_s);
  }
  if (p.feed_forward()) {
    arg(kFfLag, p.ff_lag_s * 1e6);
    arg(kFfInertia, p.ff_inertia_s2 * 1e12);
  }
  if (p.shaper_hz > 0) {
    arg(kShaperHz, p.shaper_hz);
    arg(kShaperZeta, p.shaper_zeta);
    s << " " << kShaper.name.flag << " " << to_string(p.shaper);
  }
  return s.str();
}

}  // namespace mark::cli
