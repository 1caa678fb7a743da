#pragma once
// The locus of a look-ahead plan: points at a fixed tick along moves whose speed follows their
// planned profile (speed_profile.hpp), with feed-forward and speed-proportional power.
//
// Timing: the moves and dwells lie back to back on one continuous time line from the job's
// start; sample k is the desired position at time (k + 1)·tick, wherever in a move that falls.
// Element ends need not land on a tick (the profiles already bring the speed to zero at every
// corner, so nothing is lost between two samples), and no rounding of speeds to whole ticks
// distorts the planned accelerations. The job takes ⌈duration / tick⌉ samples.
//
// Per sample: the path point P(s) at the profile's arc length s, its velocity v·T and
// acceleration a·T + v²·K (T unit tangent, K curvature vector), and the command
//   x = P + lag·(v·T) + inertia·(a·T + v²·K)
// (feed-forward: the identified model's inverse; 0/0 leaves x = P). A lit move's power is the
// path length covered in the sample's tick over full_power_speed·tick (constant dose per mm:
// the mean speed over the tick, which the laser state covers; the pulses still land v / f apart), at least 1/255 so the laser bit
// and the power agree; where that tick speed is below the move's min_lit_speed the sample is
// dark.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "marker/locus/ellipse_table.hpp"
#include "marker/plan/command.hpp"
#include "marker/plan/speed_profile.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark {

struct FeedForward {
  double lag_s = 0;       // first-order term: τ, or 2ζ/ωn
  // Second-order term: 1/ωn² (0 for a first-order model); under an input shaper, less the
  // shaper's spread (input_shaper.hpp), so it may be negative.
  double inertia_s2 = 0;
};

class PlannedLocus {
 public:
  PlannedLocus(std::span<const Command> commands, double tick_s, FeedForward ff);

  std::size_t generate(ScanSample* out, std::size_t capacity);
  bool done() const { return k_ >= total_; }
  std::uint64_t samples_written() const { return k_; }

  // Samples of the whole job: ⌈Σ durations / tick⌉.
  static std::uint64_t count_samples(std::span<const Command> commands, double tick_s);
  // Device time of the commands: Σ move profile durations + dwell ticks.
  static double duration_s(std::span<const Command> commands, double tick_s);

 private:
  bool advance();  // the next command that takes time; false at the end
  // One sample at local time tau, arc length s and speed v along the current command.
  template <CommandKind Kind, bool SecondOrder>
  void emit(ScanSample& out, double tau, double s, double v);
  template <CommandKind Kind, bool SecondOrder>
  void emit_run(ScanSample* out, std::uint64_t n);  // n samples of the current command
  template <bool SecondOrder>
  void emit_run(ScanSample* out, std::uint64_t n);

  std::span<const Command> commands_;
  double tick_s_;
  double inv_tick_;
  FeedForward ff_;
  std::uint64_t total_ = 0;
  std::uint64_t k_ = 0;          // next sample: time (k_ + 1)·tick
  std::size_t next_ = 0;         // next command to load
  std::size_t last_timed_ = 0;   // the last command that takes time
  std::vector<double> durations_;  // of every command, s
  double t0_ = 0, t_end_ = 0;    // current command's time span
  double path0_ = 0;             // path length of the job before the current command
  double loaded_length_ = 0;     // the current command's length
  double last_path_ = 0;         // path length at the previous sample
  std::int64_t k_last_ = -1;     // last sample inside the current command (−1: none loaded)

  // The current command, and the path accelerations at its neighbours' ends (second-order
  // feed-forward averages the acceleration over each sample's tick, across command ends).
  const Command* current_ = nullptr;
  Point prev_end_accel_{0, 0}, next_start_accel_{0, 0};
  CommandKind kind_ = CommandKind::dwell;
  bool laser_ = false;
  double power_per_speed_ = 0;   // 255 / full_power_speed (0: constant power)
  double min_lit_speed_ = 0;     // dark below this tick speed
  SpeedProfile profile_;
  Point p0_{0, 0}, u_{0, 0};     // line: start and unit direction; dwell: the point
  Point center_{0, 0};           // arc
  double radius_ = 0, inv_radius_ = 0, angle0_ = 0, turn_ = 1;  // arc: start angle, ±1 direction
  double arc_s_ = 0, arc_c_ = 1, arc_sn_ = 0;  // arc: the last sample's arc length, cos, sin
  int arc_steps_ = 0;                           // samples since the last exact sincos
  const EllipseTable* table_ = nullptr;         // ellipse: its table (around the origin)
  std::size_t cursor_ = 0;
  std::shared_ptr<const EllipseTable> table_hold_;  // keeps table_ alive
  static constexpr std::size_t kMaxTables = 256;
  const EllipseTable& ellipse_table(const EllipticalArc& g);
};

}  // namespace mark
