#include "marker/locus/shaped_locus.hpp"

#include <algorithm>

namespace mark {

namespace {
ScanSample dark_at(const Point& p) {
  ScanSample s;
  s.x_mm = static_cast<float>(p.x());
  s.y_mm = static_cast<float>(p.y());
  s.laser = false;
  return s;
}
}  // namespace

ShapedLocus::ShapedLocus(std::unique_ptr<PlannedLocus> planned, InputShaper shaper, std::uint64_t planned_samples,
                         Point first, Point last)
    : planned_(std::move(planned)),
      shaper_(std::move(shaper)),
      planned_total_(planned_samples),
      total_(planned_samples > 0 ? planned_samples + shaper_.tail_ticks() : 0),
      first_(dark_at(first)),
      last_(dark_at(last)) {}

std::size_t ShapedLocus::generate(ScanSample* out, std::size_t capacity) {
  const std::size_t history = shaper_.tail_ticks();
  const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(capacity, total_ - k_));
  if (n == 0) return 0;
  if (buffer_.size() < history + n) buffer_.resize(history + n);
  // This block's planned samples (what is left of the planned stream), then the rest point.
  std::size_t got = 0;
  if (k_ < planned_total_) {
    const auto want = static_cast<std::size_t>(std::min<std::uint64_t>(n, planned_total_ - k_));
    while (got < want) {
      const std::size_t g = planned_->generate(buffer_.data() + history + got, want - got);
      if (g == 0) break;  // cannot happen: planned_total_ counts the same commands
      got += g;
    }
  }
  if (k_ == 0)  // before the job: at rest on its first point
    std::fill(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(history), first_);
  std::fill(buffer_.begin() + static_cast<std::ptrdiff_t>(history + got),
            buffer_.begin() + static_cast<std::ptrdiff_t>(history + n), last_);

  const std::vector<double>& w = shaper_.taps;
  const std::size_t delay = shaper_.delay_ticks;
  for (std::size_t i = 0; i < n; ++i) {
    const ScanSample* now = buffer_.data() + history + i;
    double x = 0, y = 0;
    for (std::size_t j = 0; j < w.size(); ++j) {
      x += w[j] * now[-static_cast<std::ptrdiff_t>(j)].x_mm;
      y += w[j] * now[-static_cast<std::ptrdiff_t>(j)].y_mm;
    }
    const ScanSample& lit = now[-static_cast<std::ptrdiff_t>(delay)];
    out[i].x_mm = static_cast<float>(x);
    out[i].y_mm = static_cast<float>(y);
    out[i].laser = lit.laser;
    out[i].power = lit.power;
  }
  // Keep the last `history` planned samples for the next block.
  std::copy(buffer_.begin() + static_cast<std::ptrdiff_t>(n), buffer_.begin() + static_cast<std::ptrdiff_t>(n + history),
            buffer_.begin());
  k_ += n;
  return n;
}

}  // namespace mark
