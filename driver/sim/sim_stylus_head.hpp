#pragma once
// The simulated electromechanical engraving head, a sample-level device: the drain feeds it one
// StylusSample per 5 µs stylus tick, the drive is held for the tick (the DAC), the stylus follows
// through the head's resonances (driver/sim/stylus_head_model.hpp, integrated exactly), and the
// diamond cuts the copper wherever the stylus is below the cylinder surface. What it reports:
//
// - the cut-depth profile along the track (one value per sample, µm) and, with a cell geometry,
//   every cell's depth, length, area and volume (driver/sim/stylus_cells.hpp), measured as the
//   samples arrive;
// - the sensing coil of the seed's FIG. 13–14: stylus position and velocity at every tick, each
//   with its own white noise, recorded for the head response test of the auto-tuner. The two
//   noises are independent (the seed's circuit derives position by integrating and velocity by
//   differentiating): a fixed rms in µm on the position hurts at high frequency, where the
//   displacement is small; a fixed rms in µm/s on the velocity hurts at low frequency, where the
//   velocity ω·x is small. With the defaults they are equal, as a position, at
//   ω = 200 / 0.02 rad/s (1.6 kHz), between the head's two resonances.
//
// Safety: a sample with `lifted` set (the drain's safe sample: underrun, abort, end) retracts the
// head, and it stays retracted — cutting nothing — until the next job. halt() and abort() do the
// same at once. A drive outside the amplifier's range or not finite is refused before it reaches
// the head: the block is not executed, the head retracts, and write() throws a DeviceFaultError
// (category out_of_field) naming the sample and the value.
//
// Lifecycle: the one of driver/device.hpp (driver/lifecycle.hpp); misuse — begin_job while a
// job runs, a write outside a running job, set_recording during one — throws DeviceStateError.
//
// Threads: write()/halt() on the drain thread; abort() and status() from any thread; the
// recordings are read after end_job(). begin_job() reserves every buffer, so writing never
// allocates.
#include <atomic>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "driver/device.hpp"
#include "driver/lifecycle.hpp"
#include "driver/sim/stylus_cells.hpp"
#include "driver/sim/stylus_head_model.hpp"
#include "ringbuffer/stylus_sample.hpp"

namespace mark {

struct SimStylusHeadOptions {
  StylusHeadModel head = default_stylus_head();
  double max_drive_um = 1000;          // amplifier range: |drive| above it is refused
  double sense_noise_um = 0.02;        // rms noise on the sensing coil's position
  double sense_velocity_noise_um_s = 200;  // rms noise on its velocity (0.2 mm/s)
  std::uint32_t noise_seed = 1;        // the noise is reproducible (both, independently)
  std::optional<CellGeometry> cells;   // measure cells when set
  bool record_profile = true;          // keep the cut depth of every sample
  bool record_sense = false;           // keep the sensed position and velocity of every sample
  // Recordings are refused at begin_job for jobs longer than this (4 B per sample and record).
  std::uint64_t max_record_samples = 1ull << 25;
};

class SimStylusHead : public SampleDevice<StylusSample> {
 public:
  explicit SimStylusHead(SimStylusHeadOptions options = {});

  // Device
  DeviceDescription describe() const override;
  // Needs header.expected_samples when recording or measuring cells (buffers are sized from it);
  // throws std::invalid_argument if it exceeds max_record_samples (the head stays idle).
  void begin_job(const JobHeader& header) override;
  DeviceReport end_job() override;
  void abort() noexcept override;
  DeviceStatus status() const override;
  void reset() override;

  // Sink
  void write(std::span<const StylusSample> block) override;
  void halt() noexcept override;

  // What the next jobs record (between jobs only; DeviceStateError while one runs): the head
  // response test needs the sensing coil, an engraving job the cut profile.
  void set_recording(bool profile, bool sense);

  // Results of the last job.
  const std::vector<float>& cut_profile_um() const { return profile_; }
  const std::vector<float>& sensed_position_um() const { return sense_position_; }
  const std::vector<float>& sensed_velocity_um_s() const { return sense_velocity_; }
  const std::vector<CellFigures>& cells() const;
  std::uint64_t samples() const { return samples_.load(std::memory_order_relaxed); }
  double device_time_s() const { return static_cast<double>(samples()) * kStylusTick_s; }
  bool lifted() const { return lifted_.load(std::memory_order_relaxed); }
  double drive_peak_um() const { return drive_peak_; }
  double max_cut_um() const { return max_cut_; }
  const SimStylusHeadOptions& options() const { return options_; }

 private:
  struct Mode {
    ModeStep step;
    double x = 0;  // µm
    double v = 0;  // µm/s
  };
  void check_block(std::span<const StylusSample> block);
  void settle_at(double drive_um);
  [[noreturn]] void fail(FaultCategory category, const std::string& message, std::uint64_t at);

  SimStylusHeadOptions options_;
  std::vector<Mode> modes_;
  std::optional<CellMeter> meter_;
  std::vector<float> profile_, sense_position_, sense_velocity_;
  std::mt19937 noise_rng_, velocity_noise_rng_;  // separate, so the position noise is that of
                                                  // a head without a velocity coil
  std::normal_distribution<float> noise_{0.0f, 1.0f}, velocity_noise_{0.0f, 1.0f};
  Lifecycle lifecycle_;
  std::atomic<bool> lifted_{true};
  std::atomic<bool> cutting_{false};
  std::atomic<std::uint64_t> samples_{0};
  double drive_peak_ = 0;
  double max_cut_ = 0;
  std::uint64_t cut_samples_ = 0;
};

}  // namespace mark
