#include "marker/cli/pen_options.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/limits/pen_limits.hpp"

namespace mark::cli {
namespace {

std::string exact(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace

void add_pen_options(CLI::App& app, PenArgs& a, bool with_speed) {
  app.add_option("--corner", a.corner, "corner strategy: blanking, delays, none")->capture_default_str();
  if (with_speed)
    add_ranged_option(app, "--speed", a.speed_mm_s, "marking speed, mm/s (with --lookahead: the most; at most the head's limit)",
                      kSpeedRange)
        ->capture_default_str();
  add_ranged_option(app, "--jump-speed", a.jump_speed_mm_s,
                    "jump speed, mm/s (default: half the head's positioning limit; at most the limit)",
                    Range{1, kSpeedRange.max, "mm/s"});
  add_ranged_option(app, "--tick", a.tick_us, "locus tick, µs (at most 20 % of the head's τ)", kTickRange)
      ->capture_default_str();
  app.add_option("--head-profile", a.head_profile,
                 "the planner's model of the head: a profile from `marker head identify` "
                 "(default: the head's datasheet values)");
  app.add_flag("--lookahead", a.lookahead,
               "plan the speed along every move within the head's acceleration (docs/speed.md)");
  app.add_flag("--feed-forward", a.feed_forward,
               "pre-compensate every command by the head model so the beam follows the path "
               "(implies --lookahead)");
  auto opt = [&](const char* name, std::optional<double>& v, const char* help, const Range& range) {
    add_ranged_option(app, name, v, help, range)->group("Pen parameters (override the defaults)");
  };
  // Delays and lags: a few τ of the slowest head at most; 100 ms is far beyond any of them.
  const Range delay_us{0, 100000, "µs"};
  const Range settle_um{0, 1000, "µm"};
  const Range accel{0, 1e10, "mm/s²"};
  const Range speed{0, kSpeedRange.max, "mm/s"};
  opt("--laser-on-delay-us", a.laser_on_delay_us, "laser-on edges delayed against the mirrors, µs", delay_us);
  opt("--laser-off-delay-us", a.laser_off_delay_us, "laser-off edges delayed against the mirrors, µs", delay_us);
  opt("--jump-delay-us", a.jump_delay_us, "delays: wait after every jump, µs", delay_us);
  opt("--jump-settle-um", a.jump_settle_um, "delays: lengthen jump delays until the transient is this small, µm (0: off)",
      settle_um);
  opt("--mark-delay-us", a.mark_delay_us, "delays: wait after a stroke's last mark, µs", delay_us);
  opt("--polygon-delay-us", a.polygon_delay_us, "delays: lit wait at a corner × (1 − cos φ), µs", delay_us);
  opt("--blank-angle-deg", a.blank_angle_deg, "blanking: corners turning more than this are blanked, degrees",
      Range{0, 180, "degrees"});
  opt("--run-in", a.run_in_mm, "blanking run-in length, mm (default: sized by the head's settling)", kExtensionRange);
  opt("--min-run-in", a.min_run_in_mm, "blanking: shortest automatic run-in, mm", kExtensionRange);
  opt("--run-out", a.run_out_mm, "blanking run-out length, mm", kExtensionRange);
  opt("--settle-um", a.settle_um, "blanking: transient left when the laser switches on, µm", settle_um);
  opt("--join-speed", a.join_speed_mm_s, "blanking: speed of the line joining run-out and run-in, mm/s", speed);
  opt("--tracking-error-us", a.tracking_error_us, "the lag the delays and run-ins are sized for, µs", delay_us);
  opt("--accel", a.accel_mm_s2, "look-ahead: acceleration on lit moves and arrivals, mm/s²", accel);
  opt("--jump-accel", a.jump_accel_mm_s2, "look-ahead: acceleration on laser-off moves, mm/s²", accel);
  opt("--curve-accel", a.curve_accel_mm_s2, "look-ahead: centripetal acceleration on curves, mm/s²", accel);
  opt("--accel-limit", a.accel_limit_mm_s2,
      "look-ahead: the head's acceleration limit, shared by tangential and centripetal on curves, mm/s²", accel);
  opt("--junction-dv", a.junction_dv_mm_s, "look-ahead: velocity step allowed at a turn without a stop, mm/s", speed);
  opt("--laser-switch-speed", a.laser_switch_speed_mm_s,
      "look-ahead: speed the laser may switch at where the path runs straight on, mm/s", speed);
  opt("--min-lit-speed", a.min_lit_speed_mm_s, "look-ahead: lit moves are dark below this speed, mm/s", speed);
  opt("--ff-lag-us", a.ff_lag_us, "feed-forward: the model's ramp lag (τ or 2ζ/ωn), µs", delay_us);
  opt("--ff-inertia-us2", a.ff_inertia_us2, "feed-forward: the model's 1/ωn² (0: first order), µs²",
      Range{0, 1e10, "µs²"});
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

Pen make_pen(const PenArgs& a, const HeadModel& head) {
  // Each option's own range was checked while parsing; these depend on the head.
  const Range head_speeds{kSpeedRange.min, head.max_speed_mm_s, "mm/s (head " + head.name + "'s positioning limit)"};
  check_range("--speed", a.speed_mm_s, head_speeds);
  if (a.jump_speed_mm_s)
    check_range("--jump-speed", *a.jump_speed_mm_s,
                Range{1, head.max_speed_mm_s, "mm/s (head " + head.name + "'s positioning limit)"});
  check_range("--tick", a.tick_us, Range{kMinTick_s * 1e6, head.max_tick_s() * 1e6, "µs (20 % of the head's τ)"});
  PenRules rules;
  rules.lookahead = a.lookahead;
  // A model given by hand turns feed-forward on; a zero one compensates nothing, so it does not.
  rules.feed_forward = a.feed_forward || a.ff_lag_us.value_or(0) > 0 || a.ff_inertia_us2.value_or(0) > 0;
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
  return pen;
}

std::string pen_args_string(const Pen& p) {
  std::ostringstream s;
  s << "--corner " << to_string(p.corner) << " --speed " << exact(p.mark_speed_mm_s)
    << " --jump-speed " << exact(p.jump_speed_mm_s) << " --tick " << exact(p.tick_s * 1e6)
    << " --laser-on-delay-us " << exact(p.laser_on_delay_s * 1e6) << " --laser-off-delay-us "
    << exact(p.laser_off_delay_s * 1e6) << " --tracking-error-us " << exact(p.tracking_error_s * 1e6);
  switch (p.corner) {
    case CornerStrategy::delays:
      s << " --jump-delay-us " << exact(p.jump_delay_s * 1e6) << " --jump-settle-um "
        << exact(p.jump_settle_mm * 1e3) << " --mark-delay-us " << exact(p.mark_delay_s * 1e6)
        << " --polygon-delay-us " << exact(p.polygon_delay_s * 1e6);
      break;
    case CornerStrategy::blanking:
      s << " --blank-angle-deg " << exact(p.blank_angle_deg);
      if (p.run_in_mm) s << " --run-in " << exact(*p.run_in_mm);
      s << " --min-run-in " << exact(p.min_run_in_mm) << " --run-out " << exact(p.run_out_mm)
        << " --settle-um " << exact(p.settle_mm * 1e3) << " --join-speed "
        << exact(p.join_speed_mm_s);
      break;
    case CornerStrategy::none: break;
  }
  if (p.lookahead || p.feed_forward())
    s << " --lookahead --accel " << exact(p.accel_mm_s2) << " --jump-accel "
      << exact(p.jump_accel_mm_s2) << " --curve-accel " << exact(p.curve_accel_mm_s2)
      << " --accel-limit " << exact(p.accel_limit_mm_s2)
      << " --junction-dv " << exact(p.junction_dv_mm_s) << " --laser-switch-speed "
      << exact(p.laser_switch_speed_mm_s) << " --min-lit-speed " << exact(p.min_lit_speed_mm_s);
  if (p.feed_forward())
    s << " --ff-lag-us " << exact(p.ff_lag_s * 1e6) << " --ff-inertia-us2 "
      << exact(p.ff_inertia_s2 * 1e12);
  return s.str();
}

}  // namespace mark::cli
