#pragma once
// Command streams for the simulator tests, written straight as samples (no planner): constant-
// speed straight moves and holds, the way a locus generator would emit them.
#include <cmath>
#include <vector>

#include "driver/vec2.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark::test {

class Stream {
 public:
  explicit Stream(double tick_s = 10e-6, Vec2 start = {0, 0}) : tick_s_(tick_s), at_(start) {}

  // Move from the current point to `to` at speed_mm_s (the last sample lands on `to`; the
  // step is shortened evenly so it divides the length).
  Stream& move(Vec2 to, double speed_mm_s, bool laser) {
    const double len = norm(to - at_);
    const int n = std::max(1, static_cast<int>(std::ceil(len / (speed_mm_s * tick_s_) - 1e-9)));
    for (int i = 1; i <= n; ++i) emit(at_ + (static_cast<double>(i) / n) * (to - at_), laser);
    at_ = to;
    return *this;
  }
  // Hold the current point for n ticks.
  Stream& hold(int n, bool laser) {
    for (int i = 0; i < n; ++i) emit(at_, laser);
    return *this;
  }
  // Jump: the first sample is the target (a step), then hold to let the mirrors settle.
  Stream& step_to(Vec2 to, int settle_ticks) {
    at_ = to;
    return hold(settle_ticks, false);
  }

  const std::vector<ScanSample>& samples() const { return samples_; }
  double duration_s() const { return static_cast<double>(samples_.size()) * tick_s_; }

 private:
  void emit(Vec2 p, bool laser) {
    samples_.push_back({static_cast<float>(p.x), static_cast<float>(p.y), laser, 255});
  }
  double tick_s_;
  Vec2 at_;
  std::vector<ScanSample> samples_;
};

}  // namespace mark::test
