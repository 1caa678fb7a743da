#pragma once
// The locus generator (the seed's arithmetic operation means): drawing commands → points of locus
// at a fixed tick, each with its laser bit. Moves run at constant speed along their element,
// dwells repeat the current point. It streams: generate() fills the caller's block and returns,
// so a producer can write the job into the line memory block by block while the drain reads it —
// the whole job never exists as samples.
//
// Timing: the ideal time of the job runs on continuously (Σ length / speed); every element ends
// on the tick nearest its ideal end time, with its last sample exactly on its end point, and the
// fraction left over is carried into the next element. So no time or length error accumulates:
// over any number of elements the sample count stays within half a tick of the ideal, and every
// element is traversed over exactly its length.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "marker/locus/path_walker.hpp"
#include "marker/locus/planned_locus.hpp"
#include "marker/locus/shaped_locus.hpp"
#include "marker/plan/command.hpp"
#include "marker/plan/plan.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark {

class LocusGenerator {
 public:
  LocusGenerator(std::span<const Command> commands, double tick_s);
  // A plan's locus at its pen's tick: constant-speed as above, or — when the pen plans speeds
  // (look-ahead, feed-forward) — the planned locus with the pen's feed-forward
  // (planned_locus.hpp), through the pen's input shaper when it has one (shaped_locus.hpp). The
  // plan must outlive the generator.
  explicit LocusGenerator(const Plan& plan);
  ~LocusGenerator();

  // Writes up to `capacity` samples to `out`; returns how many (0 once the job is done).
  std::size_t generate(ScanSample* out, std::size_t capacity);
  bool done() const {
    if (shaped_) return shaped_->done();
    return profiled_ ? profiled_->done() : remaining_ == 0 && next_ >= commands_.size();
  }
  std::uint64_t samples_written() const { return emitted_; }

  // The number of samples the commands produce at this tick, without generating them.
  static std::uint64_t count_samples(std::span<const Command> commands, double tick_s);
  static std::uint64_t count_samples(const Plan& plan);

 private:
  // Sets up the next command with at least one sample; false when none is left.
  bool advance();

  std::span<const Command> commands_;
  double tick_s_;
  std::unique_ptr<PlannedLocus> profiled_;  // set when the pen plans speeds without a shaper
  std::unique_ptr<ShapedLocus> shaped_;     // set when it plans them with one
  std::size_t next_ = 0;
  double ideal_ticks_ = 0;      // ideal end time of the commands so far, in ticks
  std::uint64_t emitted_ = 0;   // samples written (= ticks elapsed)
  std::uint64_t planned_ = 0;   // samples through the end of the current command

  CommandKind kind_ = CommandKind::dwell;
  std::uint32_t step_ = 0, remaining_ = 0;
  bool laser_ = false;
  float hold_x_ = 0, hold_y_ = 0;  // dwell point
  PathWalker walker_;
};

}  // namespace mark
