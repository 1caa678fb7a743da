#include "path_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "marker/cnc/element_distance.hpp"
#include "marker/geometry/flatten.hpp"

namespace mark::test {

// Beyond this many cells an element or a query is not worth the grid: a linear look instead.
constexpr std::int64_t kNearSetMaxCells = 4096;

std::int64_t NearSet::cell_of(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }

void NearSet::add(const Element& e) {
  const auto k = static_cast<std::uint32_t>(elements_.size());
  elements_.push_back(e);
  const Box& b = boxes_.emplace_back(e.bounds());
  const std::int64_t i0 = cell_of(b.min.x()), i1 = cell_of(b.max.x()), j0 = cell_of(b.min.y()), j1 = cell_of(b.max.y());
  if ((i1 - i0 + 1) * (j1 - j0 + 1) > kNearSetMaxCells) {
    wide_.push_back(k);
    return;
  }
  for (std::int64_t i = i0; i <= i1; ++i)
    for (std::int64_t j = j0; j <= j1; ++j) cells_[key(i, j)].push_back(k);
}

void NearSet::consider(std::uint32_t k, const Point& p, double& best) const {
  const Box& b = boxes_[k];
  if (p.x() < b.min.x() - best || p.x() > b.max.x() + best || p.y() < b.min.y() - best || p.y() > b.max.y() + best)
    return;
  best = std::min(best, distance_to_element(p, elements_[k]));
}

double NearSet::distance(const Point& p, double beyond) const {
  double best = beyond;
  const std::int64_t i0 = cell_of(p.x() - beyond), i1 = cell_of(p.x() + beyond);
  const std::int64_t j0 = cell_of(p.y() - beyond), j1 = cell_of(p.y() + beyond);
  if ((i1 - i0 + 1) * (j1 - j0 + 1) > kNearSetMaxCells) {
    for (std::uint32_t k = 0; k < elements_.size(); ++k) consider(k, p, best);
    return best;
  }
  for (std::uint32_t k : wide_) consider(k, p, best);
  for (std::int64_t i = i0; i <= i1; ++i)
    for (std::int64_t j = j0; j <= j1; ++j)
      if (const auto it = cells_.find(key(i, j)); it != cells_.end())
        for (std::uint32_t k : it->second) consider(k, p, best);
  return best;
}

SegmentGrid::SegmentGrid(const Box& area, double cell) : area_(area), cell_(cell) {
  nx_ = std::max(1, static_cast<int>(std::ceil(area.width() / cell)));
  ny_ = std::max(1, static_cast<int>(std::ceil(area.height() / cell)));
  cells_.resize(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_));
}

int SegmentGrid::cx(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - area_.min.x()) / cell_)), 0, nx_ - 1);
}
int SegmentGrid::cy(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - area_.min.y()) / cell_)), 0, ny_ - 1);
}

void SegmentGrid::add(const Point& a, const Point& b) {
  segments_.push_back({a, b});
  for (int i = cx(std::min(a.x(), b.x())); i <= cx(std::max(a.x(), b.x())); ++i)
    for (int j = cy(std::min(a.y(), b.y())); j <= cy(std::max(a.y(), b.y())); ++j)
      cells_[static_cast<std::size_t>(j) * nx_ + i].push_back(segments_.size() - 1);
}

double SegmentGrid::distance(const Point& p, double cap) const {
  double best = cap;
  const int r = static_cast<int>(std::ceil(cap / cell_));
  const int i0 = cx(p.x()), j0 = cy(p.y());
  for (int i = std::max(0, i0 - r); i <= std::min(nx_ - 1, i0 + r); ++i)
    for (int j = std::max(0, j0 - r); j <= std::min(ny_ - 1, j0 + r); ++j)
      for (std::size_t k : cells_[static_cast<std::size_t>(j) * nx_ + i])
        best = std::min(best, distance_to_segment(p, segments_[k].a, segments_[k].b));
  return best;
}

bool SegmentGrid::any_within(const Point& p, double d) const {
  const int i0 = cx(p.x()), j0 = cy(p.y());
  for (std::size_t k : cells_[static_cast<std::size_t>(j0) * nx_ + i0])
    if (distance_to_segment(p, segments_[k].a, segments_[k].b) < d) return true;
  const int r = static_cast<int>(std::ceil(d / cell_));
  for (int i = std::max(0, i0 - r); i <= std::min(nx_ - 1, i0 + r); ++i)
    for (int j = std::max(0, j0 - r); j <= std::min(ny_ - 1, j0 + r); ++j) {
      if (i == i0 && j == j0) continue;
      for (std::size_t k : cells_[static_cast<std::size_t>(j) * nx_ + i])
        if (distance_to_segment(p, segments_[k].a, segments_[k].b) < d) return true;
    }
  return false;
}

std::vector<Point> samples(const Element& e, double step) {
  const int n = std::max(1, static_cast<int>(std::ceil(e.length() / step)));
  std::vector<Point> pts;
  for (int k = 0; k <= n; ++k) pts.push_back(e.point_at(static_cast<double>(k) / n));
  return pts;
}

NearSet lit_strokes(const Figure& figure) {
  NearSet set;
  for (const PlacedGlyph& g : figure.glyphs)
    for (const Element& e : g.elements)
      if (e.laser()) set.add(e);
  return set;
}

SegmentGrid stroke_grid(const Figure& figure, const Box& area, double chord_tol_mm) {
  SegmentGrid grid(area, 0.25);
  for (const PlacedGlyph& g : figure.glyphs)
    for (const Element& e : g.elements)
      if (e.laser()) {
        const std::vector<Point> pts = flatten_element(e, chord_tol_mm);
        for (std::size_t k = 1; k < pts.size(); ++k) grid.add(pts[k - 1], pts[k]);
      }
  return grid;
}

std::vector<CanonMove> cutting_moves(const std::vector<CanonMove>& moves, double z_below) {
  std::vector<CanonMove> out;
  for (const CanonMove& m : moves) {
    if (m.kind == CanonMove::traverse) continue;
    if (m.end.z() >= z_below || m.start.z() >= z_below) continue;
    if ((m.end.head<2>() - m.start.head<2>()).norm() < 1e-9 && m.kind != CanonMove::arc) continue;
    out.push_back(m);
  }
  return out;
}

}  // namespace mark::test
