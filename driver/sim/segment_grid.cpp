#include "driver/sim/segment_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mark {
namespace {

double squared_distance(Vec2 p, Vec2 a, Vec2 b, double& t) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  t = len2 > 0 ? dot(p - a, d) / len2 : 0.0;
  const Vec2 e = p - (a + std::clamp(t, 0.0, 1.0) * d);
  return dot(e, e);
}

}  // namespace

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b, double* t_out) {
  double t = 0;
  const double d2 = squared_distance(p, a, b, t);
  if (t_out) *t_out = t;
  return std::sqrt(d2);
}

SegmentGrid::SegmentGrid(std::vector<Segment> segments, double cell_mm)
    : SegmentGrid(std::make_shared<const std::vector<Segment>>(std::move(segments)), cell_mm) {}

SegmentGrid::SegmentGrid(std::shared_ptr<const std::vector<Segment>> segments, double cell_mm)
    : owner_(std::move(segments)), segments_(*owner_), cell_mm_(cell_mm) {
  if (!(cell_mm > 0)) throw std::invalid_argument("segment grid cell must be positive");
  if (segments_.empty()) return;
  Vec2 lo = segments_[0].a, hi = lo;
  for (const Segment& s : segments_)
    for (Vec2 p : {s.a, s.b}) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
  origin_ = lo;
  const double area_cells = (hi.x - lo.x) * (hi.y - lo.y) / (cell_mm_ * cell_mm_);
  if (area_cells > static_cast<double>(max_cells) / 2)
    cell_mm_ *= std::sqrt(area_cells / (static_cast<double>(max_cells) / 2));
  nx_ = cell_x(hi.x) + 1;
  ny_ = cell_y(hi.y) + 1;

  // Two passes over each segment's bounding cells: count, then place (compressed rows).
  start_.assign(static_cast<std::size_t>(nx_ * ny_ + 1), 0);
  auto for_cells = [&](const Segment& s, auto&& f) {
    const std::int64_t x0 = cell_x(std::min(s.a.x, s.b.x)), x1 = cell_x(std::max(s.a.x, s.b.x));
    const std::int64_t y0 = cell_y(std::min(s.a.y, s.b.y)), y1 = cell_y(std::max(s.a.y, s.b.y));
    for (std::int64_t y = y0; y <= y1; ++y)
      for (std::int64_t x = x0; x <= x1; ++x) f(static_cast<std::size_t>(y * nx_ + x));
  };
  for (const Segment& s : segments_) for_cells(s, [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  items_.resize(start_.back());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::uint32_t i = 0; i < segments_.size(); ++i)
    for_cells(segments_[i], [&](std::size_t c) { items_[fill[c]++] = i; });
}

std::int64_t SegmentGrid::cell_x(double x) const {
  return static_cast<std::int64_t>(std::floor((x - origin_.x) / cell_mm_));
}
std::int64_t SegmentGrid::cell_y(double y) const {
  return static_cast<std::int64_t>(std::floor((y - origin_.y) / cell_mm_));
}

void SegmentGrid::scan_cell(std::int64_t x, std::int64_t y, const Query& q, Nearest& best,
                            double& best_d2) const {
  const auto c = static_cast<std::size_t>(y * nx_ + x);
  for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
    const std::uint32_t i = items_[k];
    if (i < q.first || i > q.last) continue;
    double t = 0;
    const double d2 = squared_distance(q.p, segments_[i].a, segments_[i].b, t);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = {0, i, t};
    }
  }
}

SegmentGrid::Nearest SegmentGrid::nearest(Vec2 p, int max_rings, std::uint32_t first,
                                          std::uint32_t last) const {
  const Query q{p, first, last};
  Nearest best;
  if (segments_.empty()) return best;
  double best_d2 = std::numeric_limits<double>::infinity();
  const std::int64_t cx = cell_x(p.x), cy = cell_y(p.y);
  int r = 0;
  for (; r <= max_rings; ++r) {
    // Anything in ring r or beyond is at least (r − 1)·cell away from p.
    const double reach = (r - 1) * cell_mm_;
    if (r > 0 && best_d2 <= reach * reach) break;
    // The ring, clipped to the grid; stop once it no longer touches the grid at all.
    const std::int64_t y0 = std::max<std::int64_t>(cy - r, 0), y1 = std::min(cy + r, ny_ - 1);
    const std::int64_t x0 = std::max<std::int64_t>(cx - r, 0), x1 = std::min(cx + r, nx_ - 1);
    if (y0 > y1 || x0 > x1) continue;
    for (std::int64_t y = y0; y <= y1; ++y) {
      if (y == cy - r || y == cy + r) {
        for (std::int64_t x = x0; x <= x1; ++x) scan_cell(x, y, q, best, best_d2);
      } else {
        if (cx - r >= 0 && cx - r < nx_) scan_cell(cx - r, y, q, best, best_d2);
        if (r > 0 && cx + r >= 0 && cx + r < nx_) scan_cell(cx + r, y, q, best, best_d2);
      }
    }
  }
  best.distance = std::sqrt(best_d2);
  // Not confirmed: something one ring further out could still be closer.
  if (r > max_rings && best.distance > max_rings * cell_mm_) return Nearest{};
  return best;
}

bool SegmentGrid::any_within(Vec2 p, double radius) const {
  if (segments_.empty()) return false;
  const std::int64_t x0 = std::max<std::int64_t>(cell_x(p.x - radius), 0);
  const std::int64_t x1 = std::min(cell_x(p.x + radius), nx_ - 1);
  const std::int64_t y0 = std::max<std::int64_t>(cell_y(p.y - radius), 0);
  const std::int64_t y1 = std::min(cell_y(p.y + radius), ny_ - 1);
  const double r2 = radius * radius;
  for (std::int64_t y = y0; y <= y1; ++y)
    for (std::int64_t x = x0; x <= x1; ++x) {
      const auto c = static_cast<std::size_t>(y * nx_ + x);
      for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
        const Segment& s = segments_[items_[k]];
        double t = 0;
        if (squared_distance(p, s.a, s.b, t) <= r2) return true;
      }
    }
  return false;
}

}  // namespace mark
