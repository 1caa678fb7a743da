#include "marker/cnc/tool/edge_scan.hpp"

#include <algorithm>
#include <cmath>

namespace mark {

EdgeLevels edge_levels(const GrayImage& img) {
  std::vector<float> v = img.pixels;
  const std::size_t lo = v.size() / 50, hi = v.size() - 1 - v.size() / 50;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(lo), v.end());
  const float dark = v[lo];
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(hi), v.end());
  return {dark, v[hi]};
}

namespace {

// One line of samples: get(k) for k in [0, n); emits crossings at positions along the line.
template <class Get, class Emit>
void scan_line(int n, Get get, float level, float min_step, Emit emit) {
  for (int k = 0; k + 1 < n; ++k) {
    const float a = get(k), b = get(k + 1);
    if ((a < level) == (b < level)) continue;
    if (std::abs(get(std::min(k + 3, n - 1)) - get(std::max(k - 2, 0))) < min_step) continue;
    emit(k + 0.5 + (level - a) / (b - a));
  }
}

}  // namespace

std::vector<EdgePoint> scan_edges(const GrayImage& img, const EdgeLevels& lv, double sharpness) {
  std::vector<EdgePoint> out;
  const float level = lv.threshold();
  const float min_step = static_cast<float>(sharpness) * lv.contrast();
  for (int y = 0; y < img.height; ++y)
    scan_line(img.width, [&](int x) { return img.at(x, y); }, level, min_step,
              [&](double x) { out.push_back({Point(x, y + 0.5), Point(1, 0)}); });
  for (int x = 0; x < img.width; ++x)
    scan_line(img.height, [&](int y) { return img.at(x, y); }, level, min_step,
              [&](double y) { out.push_back({Point(x + 0.5, y), Point(0, 1)}); });
  return out;
}

}  // namespace mark
