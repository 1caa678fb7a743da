#pragma once
// Look-ahead and feed-forward on a board with its own clock (the LMC): the host plans the motion
// at its tick — the speed profile, the pre-compensated coordinates, the laser delay line — as
// for a sample-level device, and the board runs only straight moves at constant speed. So the
// locus is cut into timed moves (driver/device_command.hpp): each replaces a run of samples,
// goes straight from the run's first point to its last in as many ticks as the run spans, and
// stepping it at its constant speed puts the mirrors' command, tick by tick, within `tolerance`
// of where the locus put it. Where the locus bends or changes speed the moves are short; on a
// straight at constant speed they are long (up to `max_ticks`); where the mirrors hold (a
// dwell, a laser delay's tail) the move goes nowhere and the board holds for its time.
//
// The greedy cut: a run grows by one sample while every sample inside it stays within the
// tolerance of the straight, evenly timed move and its laser bit stays the same; the first
// sample that breaks it starts the next run (which begins at the last sample of this one). Each
// sample is checked against its move's point at its own tick, so the error bounds time and path
// together: a run that slows down fails the check as one that bends does. A lit run also keeps
// its samples' powers within a spread (look-ahead's power ∝ speed): the move carries their mean
// as its power fraction, which the board sets with its power word.
#include <cstddef>
#include <span>
#include <vector>

#include "driver/device.hpp"
#include "marker/job/device_program.hpp"
#include "marker/plan/plan.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark {

struct TimedMoveLimits {
  // About one DAC unit of a 110 mm lens (16 bits: 1.7 µm): a finer cut only adds words the
  // board rounds away.
  double tolerance_mm = 0.002;
  std::size_t max_ticks = 256;  // a move's longest span: 2.56 ms at 10 µs
  // The most a lit run's sample powers (0..255 of the pen's) may spread: the move gets their
  // mean, so a ramp's power is cut into steps of about 4 %. A spread of 3 (1 %) cut cps's 62
  // characters into 14 620 moves instead of 6 667 for the same quality classes on every plant,
  // and twice the words is what a board's list buffer and the USB link have to keep up with.
  int power_spread = 10;
};

class TimedMoves {
 public:
  TimedMoves(double tick_s, std::vector<DeviceCommand>& out, TimedMoveLimits limits = {});

  // The locus, block by block, with the laser bits as they leave the delay line.
  void add(std::span<const ScanSample> block);
  // Emits the last run.
  void finish();

  // The largest distance of a sample from its move's point at its tick (mm), over the moves
  // emitted so far: what the cut itself costs, before the board's rounding.
  double max_error_mm() const { return max_error_mm_; }

 private:
  bool fits(const ScanSample& next) const;
  void emit();

  double tick_s_;
  TimedMoveLimits limits_;
  std::vector<DeviceCommand>& out_;
  std::vector<ScanSample> run_;  // the run's samples, its start point first
  int power_min_ = 255, power_max_ = 0;  // over run_[1..]
  double max_error_mm_ = 0;
};

// A look-ahead or feed-forward plan (plan_figure, not plan_for_device) as a command-level
// device takes it: the locus with the pen's laser delays, as timed moves, every point checked
// against the device's field (DeviceFaultError, as device_program). The device pen carries no
// delays: the locus has them.
DeviceProgram timed_program(const Plan& plan, const LaserSettings& laser,
                            const DeviceDescription& device);

}  // namespace mark
