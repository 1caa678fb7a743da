#include "driver/sim/sim_scanner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "driver/device_error.hpp"
#include "driver/laser_source.hpp"

namespace mark {
namespace {

// Dose can land away from the planned lit path by the head's lag (up to about v·τ where a
// strategy cuts a corner) plus the bilinear splat; tiles within this margin are sized up front.
double dose_margin_mm(const JobHeader& header, const HeadModel& servo, const Plant& plant) {
  double fastest = 0;
  for (const DevicePen& p : header.pens) fastest = std::max(fastest, p.mark_speed_mm_s);
  if (fastest <= 0) fastest = servo.max_speed_mm_s;
  return 2 * std::min(fastest, servo.max_speed_mm_s) * (servo.tau_s + (plant.dead_us + plant.latency_us) * 1e-6) +
         4 * plant.noise_um * 1e-3 + 0.05;
}

// The preset's servo as the plant has it: the ramp lag × tau_scale (ζ kept, so ωn ÷ tau_scale);
// a second-order ωn × wn_scale at that lag (ζ × wn_scale); the plant's acceleration limit.
HeadModel plant_servo(HeadModel h, const Plant& p) {
  h.tau_s *= p.tau_scale;
  if (h.second_order) h.zeta *= p.wn_scale;
  if (p.accel_max_mm_s2 > 0) h.max_accel_mm_s2 = p.accel_max_mm_s2;
  return h;
}

int substeps_of(double us, const SimScannerOptions& o) {
  return static_cast<int>(std::lround(us * 1e-6 / (o.tick_s / o.substeps)));
}

double polyline_length(const std::vector<Vec2>& line) {
  double len = 0;
  for (std::size_t i = 1; i < line.size(); ++i) len += norm(line[i] - line[i - 1]);
  return len;
}

}  // namespace

SimScanner::SimScanner(SimScannerOptions options)
    : options_(std::move(options)),
      servo_(plant_servo(options_.head, options_.plant)),
      commands_(std::max(1, options_.substeps), std::max(0, substeps_of(options_.plant.latency_us, options_))),
      resonance_(options_.plant.resonance_hz, options_.plant.resonance_zeta, options_.tick_s / std::max(1, options_.substeps)),
      noise_(options_.plant.noise_um * 1e-3, servo_.tau_s, options_.tick_s / std::max(1, options_.substeps)),
      heat_(options_.plant.rms_accel_pct / 100, options_.plant.thermal_tau_s, options_.tick_s / std::max(1, options_.substeps)),
      dose_(options_.pixel_mm),
      pulse_dose_(options_.pixel_mm),
      lifecycle_("sim " + options_.head.name) {
  const HeadModel& h = options_.head;
  if (!(options_.tick_s > 0)) throw DeviceError("simulated scanner: tick must be positive");
  if (options_.substeps < 1) throw DeviceError("simulated scanner: substeps must be at least 1");
  if (!(h.tau_s > 0) || !(h.max_speed_mm_s > 0) || !(h.max_accel_mm_s2 > 0) || !(h.field_mm > 0))
    throw DeviceError("simulated scanner: head " + h.name +
                      " needs positive tau, speed and acceleration limits and field");
  const Plant& p = options_.plant;
  if (!(p.tau_scale > 0) || !(p.wn_scale > 0) || !(p.dead_us >= 0) || !(p.latency_us >= 0) || !(p.resonance_hz >= 0) ||
      !(p.resonance_zeta > 0) || !(p.accel_max_mm_s2 >= 0) || !(p.backemf_speed_mm_s >= 0) || !(p.rms_accel_pct >= 0) || !(p.thermal_tau_s > 0) || !(p.noise_um >= 0) || p.quant_bits < 0 ||
      p.quant_bits > 52 || !(p.current_tau_us >= 0) || !(p.jerk_max_mm_s3 >= 0))
    throw DeviceError("simulated scanner: head " + h.name + ": the plant needs positive scales and damping and "
                      "no negative dead time, resonance, acceleration, current lag, jerk, noise or bits");
  if (p.jerk_max_mm_s3 > 0 && p.current_tau_us == 0)
    throw DeviceError("simulated scanner: head " + h.name + ": the plant's jerk limit is the current loop's slew; it needs "
                      "the current loop (current_tau_us)");
  if (servo_.second_order)
    servo_step_ = second_order_step(servo_.omega_n(), servo_.zeta, options_.tick_s / options_.substeps);
  commands_.start({0, 0});
  noise_.start(p.seed);
  dead_substeps_ = std::max(0, substeps_of(p.dead_us, options_));
  for (auto& ring : dead_ring_) ring.assign(static_cast<std::size_t>(dead_substeps_), Axis{});
}

DeviceDescription SimScanner::describe() const {
  DeviceDescription d;
  d.name = "sim " + options_.head.name;
  d.level = DeviceLevel::samples;
  d.field_mm = options_.head.field_mm;
  d.tick_s = options_.tick_s;
  d.arcs = false;
  d.max_speed_mm_s = options_.head.max_speed_mm_s;
  d.laser_settings = true;
  d.fifo_samples = 0;
  return d;
}

void SimScanner::start_job() {
  trail_.flush();
  dose_.clear();
  pulse_dose_.clear();
  lit_points_.clear();
  lit_starts_.clear();
  lit_.runs.clear();
  lit_stale_ = false;
  trace_.clear();
  dose_scale_ = options_.light_power ? 1.0 : laser_.power_pct / 100;
  pulses_.begin(laser_.frequency_khz, options_.head.spot_diameter_um, pulses_laid_ ? &pulse_dose_ : nullptr);
  if (noise_.active()) noise_.start(options_.plant.seed);  // every job draws the same noise
  heat_.reset();  // the cooling between jobs is not simulated: every job starts cold
  overheated_ = false;
  samples_ = 0;
  was_lit_ = false;
  progress_.store(0, std::memory_order_relaxed);
}

void SimScanner::begin_job(const JobHeader& header) {
  lifecycle_.require(DeviceState::idle, "begin_job", "a job begins on an idle scanner (reset() it first)");
  if (header.field_mm > options_.head.field_mm * (1 + 1e-12)) {
    char msg[200];
    std::snprintf(msg, sizeof msg,
                  "simulated scanner (%s): the job's field %.3f mm is larger than the head's "
                  "%.3f mm",
                  options_.head.name.c_str(), header.field_mm, options_.head.field_mm);
    throw DeviceFaultError({FaultCategory::out_of_field, msg, 0});
  }
  const DevicePen pen = header.pens.empty() ? DevicePen{} : header.pens.front();
  const LaserSettings laser = pen.laser;
  if (!(laser.power_pct >= 0 && laser.power_pct <= 100) || !(laser.frequency_khz > 0) ||
      !std::isfinite(laser.frequency_khz)) {
    char msg[200];
    std::snprintf(msg, sizeof msg,
                  "simulated scanner (%s): the pen's power %g %% or pulse frequency %g kHz is "
                  "outside 0–100 %% / above 0 kHz",
                  options_.head.name.c_str(), laser.power_pct, laser.frequency_khz);
    throw DeviceFaultError({FaultCategory::device, msg, 0});
  }
  lifecycle_.begin("begin_job");
  laser_ = laser;
  mark_speed_mm_s_ = pen.mark_speed_mm_s;
  // A continuous-wave source's frequency is its PWM carrier: its light is continuous.
  pulses_laid_ = options_.pulse_picture && limits_of(laser_.source).pulsed;
  start_job();

  // Size everything the drain thread will touch, so write() never allocates.
  const double margin = dose_margin_mm(header, servo_, options_.plant);
  double lit_length = 0;
  dose_.reserve_along(header.lit_paths, margin);
  if (pulses_laid_) pulse_dose_.reserve_along(header.lit_paths, margin);
  for (const auto& line : header.lit_paths) lit_length += polyline_length(line);
  if (options_.record_lit_paths) {
    // A point is kept every lit_path_spacing along the beam plus the ends of each run; the lit
    // beam path is about as long as the planned one. Twice that, and runs for flicker.
    const std::size_t runs = 4 * header.lit_paths.size() + 64;
    lit_starts_.reserve(runs);
    lit_points_.reserve(static_cast<std::size_t>(2 * lit_length / options_.lit_path_spacing_mm) +
                        4 * runs + 1024);
  }
  if (options_.trace) trace_.reserve(header.expected_samples + 1024);
}

DeviceReport SimScanner::end_job() {
  const DeviceState s = lifecycle_.end();
  trail_.flush();
  laser_off();  // whatever the last sample said: a job ends dark
  publish_status();
  DeviceReport r;
  r.fault = lifecycle_.fault();
  r.outcome = s;
  r.samples_out = samples_;
  r.device_time_s = device_time_s();
  const PulseFigures p = pulses_.figures();
  r.figures = {{"samples", static_cast<double>(samples_)},
               {"device_time_s", device_time_s()},
               {"dose_tiles", static_cast<double>(dose_.tiles())},
               {"dose_memory_mib", static_cast<double>(dose_.memory_bytes()) / (1 << 20)},
               {"pulse_dose_memory_mib", static_cast<double>(pulse_dose_.memory_bytes()) / (1 << 20)},
               {"power_pct", laser_.power_pct},
               {"frequency_khz", laser_.frequency_khz},
               {"pulses", static_cast<double>(p.pulses)},
               {"pulse_spacing_um", p.spacing_max_um},
               {"pulse_spacing_mean_um", p.spacing_mean_um},
               {"pulse_overlap_fraction", p.overlap()}};
  return r;
}

MarkIntent SimScanner::intent() const {
  MarkIntent m;
  if (mark_speed_mm_s_ > 0) m.nominal_dose_s_per_mm = laser_.power_pct / 100 / mark_speed_mm_s_;
  // A continuous-wave source's frequency is its PWM carrier, not pulses that could leave gaps.
  if (limits_of(laser_.source).pulsed) m.pulses = pulses_.figures();
  return m;
}

// The beam itself belongs to the drain thread: abort() raises the request (the next write
// halts) and shows the laser off at once; the beam's power goes to 0 on that write or at
// end_job.
void SimScanner::abort() noexcept {
  lifecycle_.abort();
  laser_on_.store(false, std::memory_order_release);
}

DeviceStatus SimScanner::status() const {
  DeviceStatus st = lifecycle_.snapshot();
  st.position = {pos_x_.load(std::memory_order_relaxed), pos_y_.load(std::memory_order_relaxed)};
  st.laser_on = laser_on_.load(std::memory_order_relaxed) && st.state == DeviceState::running;
  st.progress = progress_.load(std::memory_order_relaxed);
  return st;
}

void SimScanner::reset() {
  lifecycle_.reset();
  trail_.flush();
  laser_off();
}

void SimScanner::fail(DeviceFault fault) {
  halt();
  throw DeviceFaultError(lifecycle_.fail(fault));
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
      throw DeviceFaultError({FaultCategory::out_of_field, msg, samples_ + i});
    }
  }
}

void SimScanner::write(std::span<const ScanSample> block) {
  const DeviceState state = lifecycle_.state();
  if (lifecycle_.stopped() || (state != DeviceState::idle && state != DeviceState::running)) {
    halt();
    lifecycle_.refuse("write", "the laser is halted until reset()");
  }
  if (state == DeviceState::idle) {  // implicit job: full power, default frequency
    lifecycle_.begin("write");
    laser_ = LaserSettings{};
    mark_speed_mm_s_ = DevicePen{}.mark_speed_mm_s;
    pulses_laid_ = false;  // no lit paths to reserve the pulse raster along: the time average
    start_job();
  }
  try {
    check_block(block);
  } catch (const DeviceFaultError& e) {
    fail(e.fault());
  }
  for (const ScanSample& s : block) {
    if (samples_ == options_.fault_at) {
      char msg[160];
      std::snprintf(msg, sizeof msg,
                    "simulated scanner (%s): injected device fault at sample %llu; laser halted",
                    options_.head.name.c_str(), static_cast<unsigned long long>(samples_));
      trail_.flush();
      fail({FaultCategory::device, msg, samples_});
    }
    follow(s);
    if (overheated_) {
      const int axis = heat_.hottest_axis();
      char msg[240];
      std::snprintf(msg, sizeof msg,
                    "simulated scanner (%s): the %c axis's rms acceleration reached %.1f %% of its peak "
                    "over the %g s thermal time constant, past the drive's %g %% limit, at sample %llu; "
                    "the drive tripped, laser halted",
                    options_.head.name.c_str(), axis == 0 ? 'x' : 'y', 100 * heat_.rms_share(axis),
                    options_.plant.thermal_tau_s, options_.plant.rms_accel_pct,
                    static_cast<unsigned long long>(samples_ - 1));
      trail_.flush();
      fail({FaultCategory::device, msg, samples_ - 1});
    }
  }
  trail_.flush();  // the raster is complete after every block
  publish_status();
}

void SimScanner::publish_status() {
  progress_.store(samples_, std::memory_order_relaxed);
  const Vec2 b = beam();
  pos_x_.store(static_cast<float>(b.x), std::memory_order_relaxed);
  pos_y_.store(static_cast<float>(b.y), std::memory_order_relaxed);
  laser_on_.store(laser_cmd_ && power_ > 0, std::memory_order_relaxed);
}

void SimScanner::halt() noexcept {
  lifecycle_.halt();
  trail_.flush();
  laser_off();
}

void SimScanner::laser_off() noexcept {
  laser_cmd_ = false;
  power_ = 0;
  lit_ref_ = 0;
  was_lit_ = false;
  laser_on_.store(false, std::memory_order_release);
}

// How far the shaft's speed may change over this sub-step, from v by dv towards what the servo
// asks: the current limit a_max, less what back-EMF takes while speeding up. Without back-EMF,
// ±a_max·dt exactly (the preset's arithmetic).
double SimScanner::allowed_dv(const Axis& a, double dv, double dt) const {
  const Plant& p = options_.plant;
  double up = servo_.max_accel_mm_s2, down = -servo_.max_accel_mm_s2;
  if (p.backemf_speed_mm_s > 0 && a.v != 0) {
    const double left = std::max(0.0, 1 - std::abs(a.v) / p.backemf_speed_mm_s);
    if (a.v > 0)
      up *= left;
    else
      down *= left;
  }
  return std::clamp(dv, down * dt, up * dt);
}

// One sub-step of one axis: the servo asks for the velocity that closes the tracking error in
// τ (first order, the command held over the sub-step) or the step of the (ωn, ζ) loop (second
// order, exact for the command moving at `rate`: second_order_step.hpp); the mirror can
// deliver neither faster than the speed and acceleration limits. The first-order demand also
// respects the braking curve √(2·a·|e|) so a saturated jump stops without overshoot.
//
// With a dead time the servo acts on `seen`, the shaft as it was that long ago (without, `seen`
// is `a`). A delayed loop has no exact matrix step: the second order is then stepped explicitly
// (stable up to ζ ≈ 7.75 on SL10 at 1 µs, as before the exact step).
void SimScanner::step_axis(Axis& a, const Axis& seen, double cmd, double rate, double dt) const {
  const HeadModel& h = servo_;
  const double e = cmd - seen.x;
  const double v0 = a.v;
  if (options_.plant.current_tau_us > 0) return step_through_current_loop(a, seen, e, dt);
  double want;  // the speed the servo asks for at the end of this sub-step
  if (h.second_order && dead_substeps_ > 0) {
    const double wn = h.omega_n();
    want = a.v + (wn * wn * e - 2 * h.zeta * wn * seen.v) * dt;
  } else if (h.second_order) {
    // The loop's exact step (stable for every ζ); where it would ask more than the mirror's
    // acceleration or speed, the mirror moves as far towards it as the limits allow.
    double x1 = a.x, v1 = a.v;
    servo_step_.apply(x1, v1, cmd, rate);
    if (allowed_dv(a, v1 - a.v, dt) == v1 - a.v && std::abs(v1) <= h.max_speed_mm_s) {
      a.x = x1;
      a.v = v1;
      a.acc = (v1 - v0) / dt;
      return;
    }
    want = v1;
  } else {
    want = e / h.tau_s;
    const double brake = std::sqrt(2 * h.max_accel_mm_s2 * std::abs(e));
    want = std::clamp(want, -brake, brake);
  }
  a.v += allowed_dv(a, want - a.v, dt);
  a.v = std::clamp(a.v, -h.max_speed_mm_s, h.max_speed_mm_s);
  a.x += a.v * dt;
  a.acc = (a.v - v0) / dt;
}

// Through the amplifier's current loop (plant current_tau_us): the servo asks for an
// acceleration — the second-order loop its own ωn²·e − 2ζωn·v, the first-order one's velocity
// loop (want − v) / (4·τi), critically damped with the current loop — within the current limit;
// the acceleration follows the demand with the loop's lag τi (exact over the sub-step for a
// demand held), no faster than the supply's slew (jerk_max). Stepped explicitly: stable while the
// sub-step is well below τi (1 µs against the 5 µs the range allows at least).
void SimScanner::step_through_current_loop(Axis& a, const Axis& seen, double e, double dt) const {
  const HeadModel& h = servo_;
  const double tau_i = options_.plant.current_tau_us * 1e-6;
  double demand;
  if (h.second_order) {
    const double wn = h.omega_n();
    demand = wn * wn * e - 2 * h.zeta * wn * seen.v;
  } else {
    const double brake = std::sqrt(2 * h.max_accel_mm_s2 * std::abs(e));
    const double want = std::clamp(e / h.tau_s, -brake, brake);
    demand = (want - a.v) / (4 * tau_i);
  }
  demand = allowed_dv(a, demand * dt, dt) / dt;
  double acc = a.acc + (demand - a.acc) * -std::expm1(-dt / tau_i);
  if (const double jerk = options_.plant.jerk_max_mm_s3; jerk > 0)
    acc = std::clamp(acc, a.acc - jerk * dt, a.acc + jerk * dt);
  const double v0 = a.v;
  a.v = std::clamp(a.v + acc * dt, -h.max_speed_mm_s, h.max_speed_mm_s);
  a.x += a.v * dt;
  a.acc = (a.v - v0) / dt;
}

void SimScanner::follow(const ScanSample& s) {
  const int n = options_.substeps;
  const double dt = options_.tick_s / n;
  commands_.push(quantised({s.x_mm, s.y_mm}, options_.head.field_mm, options_.plant.quant_bits));
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
    // Command at the start of this sub-step (first-order hold from the previous sample), as
    // late as the plant's command latency.
    const Vec2 cmd = commands_.at(j);
    const Vec2 rate = (1 / options_.tick_s) * commands_.tick_move(j);
    const Vec2 p0 = beam();
    const Vec2 v0 = beam_velocity_mm_s();
    for (int i = 0; i < 2; ++i) {
      if (dead_substeps_ == 0) {
        step_axis(axis_[i], axis_[i], i == 0 ? cmd.x : cmd.y, i == 0 ? rate.x : rate.y, dt);
        continue;
      }
      // The ring holds the shaft at the start of each of the last dead_substeps_ sub-steps.
      Axis& slot = dead_ring_[i][dead_at_];
      const Axis seen = slot;
      slot = axis_[i];
      step_axis(axis_[i], seen, i == 0 ? cmd.x : cmd.y, i == 0 ? rate.x : rate.y, dt);
    }
    if (dead_substeps_ > 0) dead_at_ = (dead_at_ + 1) % static_cast<std::size_t>(dead_substeps_);
    if (heat_.active() && heat_.step((1 / servo_.max_accel_mm_s2) * Vec2{axis_[0].acc, axis_[1].acc}))
      overheated_ = true;
    if (resonance_.active() || noise_.active()) {
      Vec2 off{0, 0};
      if (resonance_.active()) off = resonance_.step((1 / dt) * (beam_velocity_mm_s() - v0));
      if (noise_.active()) off = off + noise_.step();
      offset_ = off;
    }
    const Vec2 p1 = beam();
    const double mean_power = target_power + (power_ - target_power) * mean_share;
    pulses_.step(p0, p1, dt, target_power > 0, dose_scale_ * mean_power);

    power_ += (target_power - power_) * rise;
    if (mean_power > 0)
      trail_.add(p0, p1, dose_scale_ * mean_power * dt);
    else
      trail_.flush();
    record_lit(p0, p1, lit_ref_ > 0 && power_ >= 0.5 * lit_ref_);
    if (options_.probe) options_.probe(t0 + (j + 1) * dt, p1, power_);
  }
  ++samples_;
  if (options_.trace)
    trace_.push_back({static_cast<double>(samples_) * options_.tick_s, s.x_mm, s.y_mm, s.laser,
                      static_cast<float>(axis_[0].x), static_cast<float>(axis_[1].x)});
}

void SimScanner::record_lit(Vec2 p0, Vec2 p1, bool lit) {
  if (!options_.record_lit_paths) return;
  if (!lit) {
    was_lit_ = false;
    return;
  }
  lit_stale_ = true;
  if (!was_lit_) {
    lit_starts_.push_back(lit_points_.size());
    lit_points_.push_back(p0);
    lit_points_.push_back(p1);
    was_lit_ = true;
    return;
  }
  // Keep the newest position as the run's last point; keep a point behind it only once it is
  // spacing away from its predecessor, so a dwell does not pile up points.
  const std::size_t run_size = lit_points_.size() - lit_starts_.back();
  if (run_size >= 2 &&
      norm(lit_points_.back() - lit_points_[lit_points_.size() - 2]) < options_.lit_path_spacing_mm)
    lit_points_.back() = p1;
  else
    lit_points_.push_back(p1);
}

const LitPaths& SimScanner::lit_paths() const {
  if (lit_stale_) {
    lit_.runs.clear();
    for (std::size_t r = 0; r < lit_starts_.size(); ++r) {
      const std::size_t a = lit_starts_[r];
      const std::size_t b = r + 1 < lit_starts_.size() ? lit_starts_[r + 1] : lit_points_.size();
      lit_.runs.emplace_back(lit_points_.begin() + static_cast<std::ptrdiff_t>(a),
                             lit_points_.begin() + static_cast<std::ptrdiff_t>(b));
    }
    lit_stale_ = false;
  }
  return lit_;
}

}  // namespace mark
