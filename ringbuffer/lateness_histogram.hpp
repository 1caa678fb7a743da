#pragma once
// Block lateness of the real-time drain (how long after its deadline each block went out), in
// 1 µs bins up to 20 ms plus an overflow bin and the exact maximum: bounded memory however long
// the drain runs, median/p99 good to 1 µs.
#include <cstdint>
#include <vector>

namespace mark {

class LatenessHistogram {
 public:
  LatenessHistogram();
  void add(double lateness_us);
  std::uint64_t count() const { return count_; }
  // Quantile q ∈ [0, 1] in µs (centre of its bin; the exact maximum for q = 1). 0 when empty.
  double quantile_us(double q) const;
  double max_us() const { return max_us_; }

 private:
  static constexpr int bins_ = 20000;
  std::vector<std::uint64_t> counts_;  // bins_ + 1 (overflow)
  std::uint64_t count_ = 0;
  double max_us_ = 0;
};

}  // namespace mark
