#include "marker/head/pattern_marks.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <sstream>

namespace mark {

double otsu_threshold(const GrayImage& g) {
  std::array<double, 256> hist{};
  for (float v : g.pixels) hist[static_cast<std::size_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f)] += 1;
  const double total = static_cast<double>(g.pixels.size());
  double sum_all = 0;
  for (std::size_t i = 0; i < 256; ++i) sum_all += static_cast<double>(i) * hist[i];
  double w0 = 0, sum0 = 0, best = -1;
  std::size_t best_i = 127;
  for (std::size_t i = 0; i < 255; ++i) {
    w0 += hist[i];
    sum0 += static_cast<double>(i) * hist[i];
    const double w1 = total - w0;
    if (w0 == 0 || w1 == 0) continue;
    const double m0 = sum0 / w0, m1 = (sum_all - sum0) / w1;
    const double between = w0 * w1 * (m0 - m1) * (m0 - m1);
    if (between > best) best = between, best_i = i;
  }
  return (static_cast<double>(best_i) + 0.5) / 255.0;
}

std::string pattern_figure(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

PatternMarks::PatternMarks(const GrayImage& g) : g_(g), t_(otsu_threshold(g)) {
  std::size_t below = 0;
  for (float v : g.pixels) below += v < t_;
  dark_ = 2 * below < g.pixels.size();
}

}  // namespace mark
