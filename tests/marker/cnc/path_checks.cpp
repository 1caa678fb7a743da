#include "path_checks.hpp"

#include <cmath>
#include <limits>

#include "marker/cnc/element_distance.hpp"

namespace mark::test {

void NearSet::add(const Element& e) {
  elements_.push_back(e);
  boxes_.push_back(e.bounds());
}

double NearSet::distance(const Point& p, double beyond) const {
  double best = beyond;
  for (std::size_t k = 0; k < elements_.size(); ++k) {
    const Box& b = boxes_[k];
    if (p.x() < b.min.x() - best || p.x() > b.max.x() + best || p.y() < b.min.y() - best ||
        p.y() > b.max.y() + best)
      continue;
    best = std::min(best, distance_to_element(p, elements_[k]));
  }
  return best;
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
