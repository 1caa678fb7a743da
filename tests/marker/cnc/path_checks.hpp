#pragma once
// Test support: distances between the interpreter's moves and the Figure's strokes.
#include <vector>

#include "fonts/element.hpp"
#include "marker/layout/figure.hpp"
#include "rs274.hpp"

namespace mark::test {

// Elements with their bounds, queried by distance from a point.
class NearSet {
 public:
  void add(const Element& e);
  // Distance to the nearest element, or `beyond` when none is within `beyond`.
  double distance(const Point& p, double beyond) const;
  std::size_t size() const { return elements_.size(); }

 private:
  std::vector<Element> elements_;
  std::vector<Box> boxes_;
};

// Points every `step_mm` along an element (both ends included).
std::vector<Point> samples(const Element& e, double step_mm);

NearSet lit_strokes(const Figure& figure);

// Feed and arc moves that move in XY below z_below.
std::vector<CanonMove> cutting_moves(const std::vector<CanonMove>& moves, double z_below);

}  // namespace mark::test
