#pragma once
// The planned locus through an input shaper (marker/plan/input_shaper.hpp): every sample's
// position is the taps' weighted sum of the planned positions at it and the ticks before it;
// its laser bit and power are the planned sample's `delay_ticks` before. Before the job the
// planned stream is taken to rest at the path's first point, after it at its last, both dark
// (not at its first and last samples, which feed-forward may have moved off the path by the
// acceleration around them); the shaped job is `tail_ticks` longer, so the command comes to
// rest on the last point.
//
// The taps are positive and sum to 1, so every shaped position lies in the convex hull of
// planned ones: a job inside the field stays inside it.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "marker/locus/planned_locus.hpp"
#include "marker/plan/input_shaper.hpp"

namespace mark {

class ShapedLocus {
 public:
  // `planned` must generate with the shaper's feed-forward terms (shaper.lag_s, inertia_s2).
  ShapedLocus(std::unique_ptr<PlannedLocus> planned, InputShaper shaper, std::uint64_t planned_samples,
              Point first, Point last);

  std::size_t generate(ScanSample* out, std::size_t capacity);
  bool done() const { return k_ >= total_; }

 private:
  std::unique_ptr<PlannedLocus> planned_;
  InputShaper shaper_;
  std::uint64_t planned_total_;
  std::uint64_t total_;
  std::uint64_t k_ = 0;  // next shaped sample
  // The last tails' planned samples, then this block's: buffer_[history + i] is planned sample
  // k_ + i; past the planned end, the last position, dark.
  std::vector<ScanSample> buffer_;
  ScanSample first_{}, last_{};  // the path's first and last points, dark
};

}  // namespace mark
