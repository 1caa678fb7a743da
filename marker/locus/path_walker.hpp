#pragma once
// Walks one element in n steps of equal arc length: step j (1..n) is the point at arc length
// j·L/n, and step n is the element's end point exactly. Lines step linearly, circular arcs by a
// fixed rotation, elliptical arcs through their arc-length table. Everything is inline so the
// locus generator's per-kind loops carry no call per sample.
#include <cmath>
#include <cstdint>

#include "fonts/element.hpp"
#include "marker/locus/ellipse_table.hpp"

namespace mark {

class PathWalker {
 public:
  // Prepares `steps` ≥ 1 steps along `e`.
  void start(const Element& e, std::uint32_t steps);

  ElementKind kind() const { return kind_; }
  std::uint32_t steps() const { return n_; }
  const EllipseTable& ellipse_table() const { return table_; }

  // The point after step j (1 ≤ j < steps) of a line; j = steps is end().
  Point line_step(std::uint32_t j) const { return p0_ + static_cast<double>(j) * d_; }
  // The next point of an arc (call once per step, j = 1, 2, … < steps).
  Point arc_next() {
    const double c = cos_ * rot_c_ - sin_ * rot_s_;
    sin_ = sin_ * rot_c_ + cos_ * rot_s_;
    cos_ = c;
    return {p0_.x() + r_ * cos_, p0_.y() + r_ * sin_};
  }
  Point ellipse_step(std::uint32_t j) {
    return table_.point_at(static_cast<double>(j) * ds_, cursor_);
  }
  const Point& end() const { return end_; }

  // Generic step for tests and cold paths: the point after step j, called with j = 1, 2, … .
  Point step(std::uint32_t j) {
    if (j >= n_) return end_;
    switch (kind_) {
      case ElementKind::line: return line_step(j);
      case ElementKind::arc: return arc_next();
      case ElementKind::ellipse: return ellipse_step(j);
    }
    return end_;
  }

 private:
  ElementKind kind_ = ElementKind::line;
  std::uint32_t n_ = 1;
  Point end_{0, 0};
  Point p0_{0, 0};   // line: start; arc: centre
  Point d_{0, 0};    // line: step vector
  double r_ = 0, cos_ = 1, sin_ = 0, rot_c_ = 1, rot_s_ = 0;  // arc
  double ds_ = 0;    // ellipse: arc length per step
  EllipseTable table_;
  std::size_t cursor_ = 0;
};

}  // namespace mark
