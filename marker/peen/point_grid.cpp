#include "marker/peen/point_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mark {
namespace {

// Rings of cells searched before the nearest-unvisited query gives up on the grid and scans the
// remaining points: only stragglers far from everything reach it.
constexpr long kMaxRing = 12;

// Calls f(cell index) for every cell of the square ring at Chebyshev distance r around (cx, cy).
template <class F>
void for_ring(long cx, long cy, long r, long nx, long ny, F&& f) {
  for (long y = cy - r; y <= cy + r; ++y) {
    if (y < 0 || y >= ny) continue;
    const bool edge_row = y == cy - r || y == cy + r;
    for (long x = cx - r; x <= cx + r; x += (edge_row || r == 0) ? 1 : 2 * r) {
      if (x >= 0 && x < nx) f(static_cast<std::size_t>(y * nx + x));
    }
  }
}

}  // namespace

PointGrid::PointGrid(const MoveCost& cost) : cost_(cost) {
  const std::size_t n = cost.size();
  mm_.reserve(n);
  Box box;
  for (const StepPoint& s : cost.points()) {
    mm_.push_back(to_mm(s, cost.gantry()));
    box.add(mm_.back());
  }
  if (n == 0) return;
  x0_ = box.min.x();
  y0_ = box.min.y();
  const double area = std::max(box.width(), 1e-3) * std::max(box.height(), 1e-3);
  cell_mm_ = std::max(std::sqrt(area / static_cast<double>(n)), 1e-3);
  nx_ = std::max(1L, static_cast<long>(box.width() / cell_mm_) + 1);
  ny_ = std::max(1L, static_cast<long>(box.height() / cell_mm_) + 1);
  cells_.resize(static_cast<std::size_t>(nx_ * ny_));
  slot_.resize(n);
  unvisited_.resize(n);
  unvisited_slot_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::size_t>& c = cells_[cell_of(i)];
    slot_[i] = c.size();
    c.push_back(i);
    unvisited_[i] = i;
    unvisited_slot_[i] = i;
  }
}

long PointGrid::cell_x(double x) const {
  return std::clamp(static_cast<long>((x - x0_) / cell_mm_), 0L, nx_ - 1);
}
long PointGrid::cell_y(double y) const {
  return std::clamp(static_cast<long>((y - y0_) / cell_mm_), 0L, ny_ - 1);
}
std::size_t PointGrid::cell_of(std::size_t p) const {
  return static_cast<std::size_t>(cell_y(mm_[p].y()) * nx_ + cell_x(mm_[p].x()));
}

std::vector<std::vector<std::size_t>> PointGrid::neighbour_lists(std::size_t k) const {
  const std::size_t n = mm_.size();
  std::vector<std::vector<std::size_t>> out(n);
  std::vector<std::pair<double, std::size_t>> found;
  const long max_r = std::max(nx_, ny_);
  for (std::size_t p = 0; p < n; ++p) {
    found.clear();
    const long cx = cell_x(mm_[p].x()), cy = cell_y(mm_[p].y());
    long extra = -1;  // rings still to scan once k points are in hand
    for (long r = 0; r <= max_r && extra != 0; ++r) {
      for_ring(cx, cy, r, nx_, ny_, [&](std::size_t c) {
        for (std::size_t q : cells_[c])
          if (q != p) found.emplace_back(cost_(p, q), q);
      });
      if (extra > 0) --extra;
      if (extra < 0 && found.size() >= k) extra = 1;
    }
    const std::size_t m = std::min(k, found.size());
    std::partial_sort(found.begin(), found.begin() + static_cast<long>(m), found.end());
    out[p].reserve(m);
    for (std::size_t i = 0; i < m; ++i) out[p].push_back(found[i].second);
  }
  return out;
}

void PointGrid::visit(std::size_t p) {
  std::vector<std::size_t>& c = cells_[cell_of(p)];
  const std::size_t s = slot_[p];
  c[s] = c.back();
  slot_[c[s]] = s;
  c.pop_back();
  const std::size_t u = unvisited_slot_[p];
  unvisited_[u] = unvisited_.back();
  unvisited_slot_[unvisited_[u]] = u;
  unvisited_.pop_back();
}

std::size_t PointGrid::nearest_unvisited(std::size_t from) const {
  std::size_t best = mm_.size();
  double best_cost = std::numeric_limits<double>::infinity();
  if (unvisited_.empty()) return best;
  const long cx = cell_x(mm_[from].x()), cy = cell_y(mm_[from].y());
  const long max_r = std::max(nx_, ny_);
  for (long r = 0;; ++r) {
    if (r > max_r) return best;  // every cell scanned
    // Every point in ring r is more than (r − 1) cells away along x or y.
    if (best_cost <= cost_.lower_bound(static_cast<double>(r - 1) * cell_mm_)) return best;
    if (r > kMaxRing) break;
    for_ring(cx, cy, r, nx_, ny_, [&](std::size_t c) {
      for (std::size_t q : cells_[c]) {
        const double t = cost_(from, q);
        if (t < best_cost || (t == best_cost && q < best)) best_cost = t, best = q;
      }
    });
  }
  for (std::size_t q : unvisited_) {
    const double t = cost_(from, q);
    if (t < best_cost || (t == best_cost && q < best)) best_cost = t, best = q;
  }
  return best;
}

}  // namespace mark
