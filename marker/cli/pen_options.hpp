#pragma once
// The pen options of `marker mark` (and of anything that plans a job): the corner strategy and
// marking speed, the planner's model of the head (--head-profile, else the preset's datasheet
// values) that sets every default, and an explicit override for every pen parameter. cps prints
// its winning settings through pen_args_string(), which names every parameter explicitly, so
// `marker mark TEXT <those options>` plans exactly the pen cps measured, on any text.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "driver/device.hpp"
#include "driver/sim/head_model.hpp"
#include "marker/head/head_profile.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/plan/pen.hpp"

namespace mark::cli {

struct PenArgs {
  // Defaults from the settings table (marker/limits/pen_settings.hpp).
  std::string corner{kCorner.value};
  double speed_mm_s = *kMarkSpeed.value;
  std::optional<double> jump_speed_mm_s;
  double tick_us = *kTick.value;
  std::string head_profile;  // the planner's model of the head (JSON); empty: datasheet values
  bool lookahead = false;
  bool feed_forward = false;
  // Explicit overrides of single pen parameters (units in the option names and help).
  std::optional<double> laser_on_delay_us, laser_off_delay_us, jump_delay_us, mark_delay_us,
      polygon_delay_us, jump_settle_um, blank_angle_deg, run_in_mm, min_run_in_mm, run_out_mm,
      settle_um, join_speed_mm_s, tracking_error_us, accel_mm_s2, jump_accel_mm_s2,
      curve_accel_mm_s2, accel_limit_mm_s2, junction_dv_mm_s, laser_switch_speed_mm_s, min_lit_speed_mm_s,
      ff_lag_us, ff_inertia_us2, shaper_hz, shaper_zeta;
  std::string shaper{kShaper.value};
};

// `with_speed`: whether --speed is one of them (mark has its own, which also takes "auto").
void add_pen_options(CLI::App& app, PenArgs& args, bool with_speed = true);
// The laser source's settings: --power, --frequency, --pulse-width.
void add_laser_options(CLI::App& app, LaserSettings& laser);

// The planner's model: the profile file, or the head's datasheet profile.
HeadProfile planner_profile(const PenArgs& args, const HeadModel& head);

// The pen: defaults from the planner's model, then every explicit override. Throws InputError
// naming a bad option (unknown corner strategy, a negative or non-finite value).
Pen make_pen(const PenArgs& args, const HeadModel& head);

// Whether the pen pre-compensates by the head model: --feed-forward, or a model given by hand (a
// zero one compensates nothing, so it does not).
bool feeds_forward(const PenArgs& args);
// Refuses, in one line, a pen option this pen never reads (unread_options.hpp): a delays setting
// on a blanking pen, a blanking one on a delays pen, a look-ahead one without --lookahead or
// --feed-forward, the tracking error on a pen with no corner strategy.
void refuse_unread_pen_options(const CLI::App& app, const PenArgs& args);

// Options that reproduce `pen` exactly through make_pen, whatever the head and profile:
// "--corner none --speed 2000 --jump-speed 9600 --tick 10 --lookahead --accel 2.2e+07 …".
// Numbers are printed in their shortest exact form.
std::string pen_args_string(const Pen& pen);

}  // namespace mark::cli
