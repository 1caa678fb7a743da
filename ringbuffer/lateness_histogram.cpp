#include "ringbuffer/lateness_histogram.hpp"

#include <algorithm>
#include <cmath>

namespace mark {

LatenessHistogram::LatenessHistogram() : counts_(bins_ + 1, 0) {}

void LatenessHistogram::add(double lateness_us) {
  const double v = std::max(0.0, lateness_us);
  const int bin = v >= bins_ ? bins_ : static_cast<int>(v);
  ++counts_[static_cast<std::size_t>(bin)];
  ++count_;
  max_us_ = std::max(max_us_, v);
}

double LatenessHistogram::quantile_us(double q) const {
  if (count_ == 0) return 0;
  if (q >= 1) return max_us_;
  // The smallest bin whose cumulative count reaches ceil(q·count).
  const auto rank = static_cast<std::uint64_t>(std::ceil(std::max(q, 0.0) * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (int b = 0; b <= bins_; ++b) {
    seen += counts_[static_cast<std::size_t>(b)];
    if (seen >= std::max<std::uint64_t>(rank, 1)) return b == bins_ ? max_us_ : std::min(b + 0.5, max_us_);
  }
  return max_us_;
}

}  // namespace mark
