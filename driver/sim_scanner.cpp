#include "driver/sim_scanner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "driver/device_error.hpp"

namespace mark {

SimScanner::SimScanner(SimScannerOptions options)
    : options_(std::move(options)), dose_(options_.pixel_mm) {
  const HeadModel& h = options_.head;
  if (!(options_.tick_s > 0)) throw DeviceError("simulated scanner: tick must be positive");
  if (options_.substeps < 1) throw DeviceError("simulated scanner: substeps must be at least 1");
  if (!(h.tau_s > 0) || !(h.max_speed_mm_s > 0) || !(h.max_accel_mm_s2 > 0) || !(h.field_mm > 0))
    throw DeviceError("simulated scanner: head " + h.name +
                      " needs positive tau, speed and acceleration limits and field");
}

void SimScanner::check_block(std::span<const ScanSample> block) const {
  const double half = options_.head.half_field_mm();
  for (std::size_t i = 0; i < block.size(); ++i) {
    const double c[2] = {block[i].x_mm, block[i].y_mm};
    for (int a = 0; a < 2; ++a) {
      if (std::isfinite(c[a]) && std::abs(c[a]) <= half) continue;
      char msg[200];
      std::snprintf(msg, sizeof msg,
                    "simulated scanner (%s): sample %llu has %c = %.4f mm, outside the field "
                    "±%.3f mm; laser halted",
                    options_.head.name.c_str(),
                    static_cast<unsigned long long>(samples_ + i), a == 0 ? 'x' : 'y', c[a], half);
      throw DeviceError(msg);
    }
  }
}

void SimScanner::write(std::span<const ScanSample> block) {
  if (halted_) throw DeviceError("simulated scanner (" + options_.head.name + "): halted, laser off");
  try {
    check_block(block);
  } catch (...) {
    halt();
    throw;
  }
  for (const ScanSample& s : block) follow(s);
  trail_.flush();  // the raster is complete after every block
}

void SimScanner::halt() noexcept {
  trail_.flush();
  halted_ = true;
  laser_cmd_ = false;
  power_ = 0;
  lit_ref_ = 0;
  was_lit_ = false;
}

// One sub-step of one axis: the servo asks for the velocity that closes the tracking error in
// τ (first order) or the acceleration of the (ωn, ζ) loop (second order); the mirror can
// deliver neither faster than the speed and acceleration limits. The first-order demand also
// respects the braking curve √(2·a·|e|) so a saturated jump stops without overshoot.
void SimScanner::step_axis(Axis& a, double cmd, double dt) const {
  const HeadModel& h = options_.head;
  const double e = cmd - a.x;
  const double dv_max = h.max_accel_mm_s2 * dt;
  if (h.second_order) {
    const double wn = h.omega_n();
    const double acc = wn * wn * e - 2 * h.zeta * wn * a.v;
    a.v += std::clamp(acc * dt, -dv_max, dv_max);
  } else {
    double want = e / h.tau_s;
    const double brake = std::sqrt(2 * h.max_accel_mm_s2 * std::abs(e));
    want = std::clamp(want, -brake, brake);
    a.v += std::clamp(want - a.v, -dv_max, dv_max);
  }
  a.v = std::clamp(a.v, -h.max_speed_mm_s, h.max_speed_mm_s);
  a.x += a.v * dt;
}

void SimScanner::follow(const ScanSample& s) {
  const int n = options_.substeps;
  const double dt = options_.tick_s / n;
  const Vec2 from = cmd_, to{s.x_mm, s.y_mm};
  const double target_power = s.laser ? s.power / 255.0 : 0.0;
  // First-order laser power p → target: after a sub-step p moves by `rise` of the gap, and its
  // mean over the sub-step is target + (p − target)·`mean_share` (exact; both 1/0 when instant).
  const double tr = options_.laser_rise_s;
  const double rise = tr > 0 ? 1 - std::exp(-dt / tr) : 1.0;
  const double mean_share = tr > 0 ? tr / dt * rise : 0.0;
  const double t0 = static_cast<double>(samples_) * options_.tick_s;
  laser_cmd_ = s.laser;
  // "Lit" is relative to the power the laser was last commanded to while on: a pen at low power,
  // or power scaled with speed along a stroke, still marks; after laser-off the falling power
  // counts as lit until it is below half of the last on-power.
  if (target_power > 0) lit_ref_ = target_power;

  for (int j = 0; j < n; ++j) {
    // Command at the start of this sub-step (first-order hold from the previous sample).
    const Vec2 cmd = from + (static_cast<double>(j) / n) * (to - from);
    const Vec2 p0 = beam();
    step_axis(axis_[0], cmd.x, dt);
    step_axis(axis_[1], cmd.y, dt);
    const Vec2 p1 = beam();

    const double mean_power = target_power + (power_ - target_power) * mean_share;
    power_ += (target_power - power_) * rise;
    if (mean_power > 0)
      trail_.add(p0, p1, mean_power * dt);
    else
      trail_.flush();
    record_lit(p0, p1, lit_ref_ > 0 && power_ >= 0.5 * lit_ref_);
    if (options_.probe) options_.probe(t0 + (j + 1) * dt, p1, power_);
  }
  cmd_ = to;
  ++samples_;
}

void SimScanner::record_lit(Vec2 p0, Vec2 p1, bool lit) {
  if (!options_.record_lit_paths) return;
  if (!lit) {
    was_lit_ = false;
    return;
  }
  if (!was_lit_) {
    lit_.runs.push_back({p0, p1});
    was_lit_ = true;
    return;
  }
  auto& run = lit_.runs.back();
  // Keep the newest position as the run's last point; keep a point behind it only once it is
  // spacing away from its predecessor, so a dwell does not pile up points.
  if (run.size() >= 2 && norm(run.back() - run[run.size() - 2]) < options_.lit_path_spacing_mm)
    run.back() = p1;
  else
    run.push_back(p1);
}

}  // namespace mark
