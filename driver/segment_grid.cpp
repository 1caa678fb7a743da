#include "driver/segment_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mark {

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b, double* t_out) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  const double t = len2 > 0 ? dot(p - a, d) / len2 : 0.0;
  if (t_out) *t_out = t;
  return norm(p - (a + std::clamp(t, 0.0, 1.0) * d));
}

SegmentGrid::SegmentGrid(double cell_mm) : cell_mm_(cell_mm) {
  if (!(cell_mm > 0)) throw std::invalid_argument("segment grid cell must be positive");
}

std::uint64_t SegmentGrid::key(std::int64_t cx, std::int64_t cy) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(cx)) << 32) |
         static_cast<std::uint32_t>(cy);
}

std::int64_t SegmentGrid::cell(double v) const {
  return static_cast<std::int64_t>(std::floor(v / cell_mm_));
}

void SegmentGrid::add(Vec2 a, Vec2 b) {
  const auto i = static_cast<std::uint32_t>(segments_.size());
  segments_.push_back({a, b});
  const std::int64_t x0 = cell(std::min(a.x, b.x)), x1 = cell(std::max(a.x, b.x));
  const std::int64_t y0 = cell(std::min(a.y, b.y)), y1 = cell(std::max(a.y, b.y));
  for (std::int64_t cy = y0; cy <= y1; ++cy)
    for (std::int64_t cx = x0; cx <= x1; ++cx) cells_[key(cx, cy)].push_back(i);
}

void SegmentGrid::consider(std::uint32_t i, Vec2 p, Nearest& best) const {
  double t = 0;
  const double d = point_segment_distance(p, segments_[i].a, segments_[i].b, &t);
  if (d < best.distance) best = {d, i, t};
}

SegmentGrid::Nearest SegmentGrid::nearest(Vec2 p, int max_rings) const {
  Nearest best;
  const std::int64_t cx = cell(p.x), cy = cell(p.y);
  for (int r = 0; r <= max_rings; ++r) {
    // Anything in ring r or beyond is at least (r − 1)·cell away from p.
    if (best.distance <= (r - 1) * cell_mm_) break;
    for (std::int64_t y = cy - r; y <= cy + r; ++y) {
      const bool edge_row = (y == cy - r || y == cy + r);
      for (std::int64_t x = cx - r; x <= cx + r; x += (edge_row || r == 0) ? 1 : 2 * r) {
        const auto it = cells_.find(key(x, y));
        if (it == cells_.end()) continue;
        for (std::uint32_t i : it->second) consider(i, p, best);
      }
    }
  }
  // A result found in the last ring may still have a closer rival one ring further out.
  if (best.distance > max_rings * cell_mm_) return Nearest{};
  return best;
}

bool SegmentGrid::any_within(Vec2 p, double radius) const {
  const std::int64_t x0 = cell(p.x - radius), x1 = cell(p.x + radius);
  const std::int64_t y0 = cell(p.y - radius), y1 = cell(p.y + radius);
  for (std::int64_t y = y0; y <= y1; ++y)
    for (std::int64_t x = x0; x <= x1; ++x) {
      const auto it = cells_.find(key(x, y));
      if (it == cells_.end()) continue;
      for (std::uint32_t i : it->second)
        if (point_segment_distance(p, segments_[i].a, segments_[i].b) <= radius) return true;
    }
  return false;
}

}  // namespace mark
