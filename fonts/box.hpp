#pragma once
// Axis-aligned bounding box in whatever units the caller works in (font units or mm).
#include <Eigen/Core>
#include <algorithm>
#include <limits>

namespace mark {

using Point = Eigen::Vector2d;

struct Box {
  Point min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Point max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  bool empty() const { return min.x() > max.x(); }
  double width() const { return empty() ? 0.0 : max.x() - min.x(); }
  double height() const { return empty() ? 0.0 : max.y() - min.y(); }
  Point center() const { return (min + max) / 2.0; }

  void add(const Point& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void add(const Box& b) {
    if (b.empty()) return;
    add(b.min);
    add(b.max);
  }
  // The box with `by` added on every side.
  Box grown(double by) const {
    Box g;
    g.add(min - Point(by, by));
    g.add(max + Point(by, by));
    return g;
  }
  bool contains(const Box& b, double tol = 0.0) const {
    return b.empty() || (b.min.x() >= min.x() - tol && b.min.y() >= min.y() - tol &&
                         b.max.x() <= max.x() + tol && b.max.y() <= max.y() + tol);
  }
};

}  // namespace mark
