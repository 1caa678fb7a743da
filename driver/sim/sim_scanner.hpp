#pragma once
// The simulated scanner, the default device: two mirror axes that follow the commanded samples
// through the head model (first-order lag τ — or second-order (ωn, ζ) — plus per-axis speed and
// acceleration limits), integrated in sub-steps of the tick; a laser with an optional rise time;
// the dose the beam leaves along its real path; the lit beam path for quality figures.
//
// Timing convention: sample k is the command for the end of tick k (device time (k+1)·tick);
// during tick k the command moves linearly from sample k−1 to sample k (first-order hold, so a
// constant-speed ramp lags by exactly τ·v) and the laser is as sample k says. Device time =
// samples × tick. The beam starts at rest at the field centre with the laser off.
//
// A sample-level Device (driver/device.hpp) with the one lifecycle (driver/lifecycle.hpp).
// begin_job() clears the previous job's dose and lit paths and sizes everything the job needs —
// dose tiles along the header's lit paths, the lit path and trace buffers — so write(), on the
// drain thread, does not allocate. Samples written to an idle scanner start an implicit job with
// nothing sized (the scanner as a bare sink: verification runs, the emulated board's plant).
// end_job() leaves the laser off whatever the last sample said.
//
// Laser: the dose is time × the sample's power × the pen's power (JobHeader::pens[0].laser
// .power_pct; 100 % for an implicit job), so half the power leaves half the dose; the lit test
// (where the beam marked) does not depend on the pen's power. The pulse train at the pen's
// frequency gives the pulse spacing along the lit path and its overlap against the head's spot
// diameter (driver/sim/pulse_train.hpp).
//
// Laser safety: a block holding any sample outside the field (or not finite) is refused as a
// whole: the scanner halts (laser off) and throws DeviceFaultError (out_of_field) naming the
// sample and coordinate. After halt() or abort() every further write throws DeviceStateError;
// the laser stays off until reset().
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "driver/device.hpp"
#include "driver/lifecycle.hpp"
#include "driver/sim/dose_raster.hpp"
#include "driver/sim/dose_trail.hpp"
#include "driver/sim/head_model.hpp"
#include "driver/sim/lit_paths.hpp"
#include "driver/sim/mark_intent.hpp"
#include "driver/sim/plant.hpp"
#include "driver/sim/plant_effects.hpp"
#include "driver/sim/pulse_train.hpp"
#include "driver/sim/second_order_step.hpp"
#include "driver/sim/sim_trace.hpp"
#include "driver/vec2.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark {

struct SimScannerOptions {
  HeadModel head = head_sl10();
  // The head as it is, apart from `head` (the preset, which the planner's model describes):
  // plant.hpp. The default adds nothing.
  Plant plant;
  double tick_s = 10e-6;            // time per sample
  int substeps = 10;                // integration steps per tick (1 µs at the default tick)
  double laser_rise_s = 0;          // first-order rise/fall time constant of the laser power; 0 = instant
  double pixel_mm = 0.005;          // dose raster pixel
  bool record_lit_paths = true;     // keep the lit beam path (for quality figures)
  double lit_path_spacing_mm = 0.004;  // lit points kept about this far apart (≤ 1 per sub-step)
  bool trace = false;               // keep one SimTraceRow per sample (marker mark --trace)
  // The samples' power is the light's share of the source's full power (a board's output:
  // MarkCurrent / 4095), not a share of the pen's power, so the pen's power is not applied a
  // second time. The nominal dose (quality) is the pen's either way.
  bool light_power = false;
  // Keep a second raster of the pulses where they fired (a pulsed source only): picture_dose().
  // Costs as much memory again as the dose; a caller that takes no picture can leave it out.
  bool pulse_picture = true;
  // Fault injection (tests, `marker mark --inject fault@N`): the device reports a fault of its
  // own at this sample of a job and halts.
  std::uint64_t fault_at = UINT64_MAX;
  // Called at every sub-step with the device time, beam position and effective laser power
  // (0..1). For validation tests; leave empty otherwise.
  std::function<void(double t_s, Vec2 beam, double power)> probe;
};

class SimScanner : public SampleDevice<ScanSample> {
 public:
  explicit SimScanner(SimScannerOptions options = {});

  // Device
  DeviceDescription describe() const override;
  void begin_job(const JobHeader& header) override;
  DeviceReport end_job() override;
  void abort() noexcept override;
  DeviceStatus status() const override;
  void reset() override;

  // Sink (the drain thread)
  void write(std::span<const ScanSample> block) override;
  void halt() noexcept override;

  std::uint64_t samples() const { return samples_; }  // in this job
  double device_time_s() const { return static_cast<double>(samples_) * options_.tick_s; }
  // The laser is held off for the rest of the job: halt(), abort() or a fault.
  bool halted() const { return lifecycle_.stopped(); }
  bool laser_commanded() const { return laser_cmd_; }  // laser gate as last commanded
  double laser_power() const { return power_; }        // effective power now, 0..1
  // The beam: the servo's shaft, the mirror's twist against it and the position noise.
  Vec2 beam() const { return Vec2{axis_[0].x, axis_[1].x} + offset_; }
  Vec2 beam_velocity_mm_s() const { return {axis_[0].v, axis_[1].v}; }

  // The time average of the light along the beam's path: the quality figures' dose.
  const DoseRaster& dose() const { return dose_; }
  // The dose as the part holds it, for a camera's picture: each pulse where it fired (a pulsed
  // source, options().pulse_picture), so a fast stroke at a low frequency is a row of dots and
  // a slower one has its scallops; else (a continuous source, or samples without begin_job: no
  // pen to fire pulses at) the time average.
  const DoseRaster& picture_dose() const { return pulses_laid_ ? pulse_dose_ : dose_; }
  // The lit runs of this job (assembled from the recording buffer on first use after a write).
  const LitPaths& lit_paths() const;
  // One row per sample of this job when options().trace is set.
  const std::vector<SimTraceRow>& trace() const { return trace_; }
  const SimScannerOptions& options() const { return options_; }
  // The laser settings of this job (the header's first pen) and its pulse figures so far.
  const LaserSettings& laser() const { return laser_; }
  PulseFigures pulses() const { return pulses_.figures(); }
  // What this job's pen meant (its energy per mm, the pulses it fired), for the quality figures.
  // An implicit job (samples without begin_job) has DevicePen's defaults: 100 % at 1000 mm/s.
  MarkIntent intent() const;

 private:
  struct Axis {
    double x = 0;  // position, mm
    double v = 0;  // velocity, mm/s
    double acc = 0;  // acceleration over the last sub-step, mm/s²
  };
  void start_job();
  void laser_off() noexcept;
  void check_block(std::span<const ScanSample> block) const;
  void follow(const ScanSample& s);
  void step_axis(Axis& a, const Axis& seen, double cmd, double rate, double dt) const;
  double allowed_dv(const Axis& a, double dv, double dt) const;
  void step_through_current_loop(Axis& a, const Axis& seen, double e, double dt) const;
  void record_lit(Vec2 p0, Vec2 p1, bool lit);
  [[noreturn]] void fail(DeviceFault fault);
  void publish_status();

  SimScannerOptions options_;
  HeadModel servo_;             // the head's servo as the plant has it (τ, ζ, acceleration)
  SecondOrderStep servo_step_;  // the second-order servo's exact sub-step (unused by first order)
  Axis axis_[2];
  CommandHistory commands_;     // the samples, quantised, as the (delayed) servo sees them
  // The plant's dead time: per axis, the shaft at the start of each of the last dead_substeps_
  // sub-steps (sized by the constructor), the oldest at dead_at_.
  int dead_substeps_ = 0;
  std::vector<Axis> dead_ring_[2];
  std::size_t dead_at_ = 0;
  MirrorResonance resonance_;
  BeamNoise noise_;
  CoilHeat heat_;            // the coils' heating (the plant's thermal limit)
  bool overheated_ = false;  // set by follow(), turned into the drive's trip by write()
  Vec2 offset_{0, 0};           // the beam's offset from the shaft: twist + noise
  bool laser_cmd_ = false;
  double power_ = 0;         // effective laser power 0..1
  double lit_ref_ = 0;       // power of the last lit sample: the lit test is relative to it
  bool was_lit_ = false;
  std::uint64_t samples_ = 0;
  DoseRaster dose_;
  DoseTrail trail_{dose_};
  DoseRaster pulse_dose_;  // each pulse's dose where it fired (picture_dose)
  bool pulses_laid_ = false;  // this job (begun with begin_job) fills pulse_dose_
  // Lit beam path as recorded on the drain thread: flat points and the index where each run
  // starts, both reserved by begin_job.
  std::vector<Vec2> lit_points_;
  std::vector<std::size_t> lit_starts_;
  mutable LitPaths lit_;
  mutable bool lit_stale_ = false;
  std::vector<SimTraceRow> trace_;
  LaserSettings laser_;       // this job's pen
  double mark_speed_mm_s_ = DevicePen{}.mark_speed_mm_s;  // and its marking speed
  double dose_scale_ = 1;     // the pen's power, 0..1
  PulseTrain pulses_;

  // State shared with other threads (abort, status).
  Lifecycle lifecycle_;
  std::atomic<std::uint64_t> progress_{0};
  std::atomic<float> pos_x_{0}, pos_y_{0};
  std::atomic<bool> laser_on_{false};
};

}  // namespace mark
