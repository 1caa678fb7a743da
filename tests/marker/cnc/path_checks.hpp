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

// Line segments in a uniform grid of cells, for fast "how far is the nearest segment" queries
// over many points (the interpreter's moves of a pocketing program, thousands of them).
class SegmentGrid {
 public:
  SegmentGrid(const Box& area, double cell_mm);
  void add(const Point& a, const Point& b);
  // Distance to the nearest segment, or `cap` when none is within `cap`.
  double distance(const Point& p, double cap) const;
  // Is some segment closer than d? (Stops at the first one: cheaper than distance().)
  bool any_within(const Point& p, double d) const;

 private:
  struct Segment {
    Point a, b;
  };
  Box area_;
  double cell_;
  int nx_, ny_;
  std::vector<Segment> segments_;
  std::vector<std::vector<std::size_t>> cells_;
  int cx(double x) const;
  int cy(double y) const;
};

// Points every `step_mm` along an element (both ends included).
std::vector<Point> samples(const Element& e, double step_mm);

NearSet lit_strokes(const Figure& figure);
// The lit strokes flattened within chord_tol_mm into a SegmentGrid over `area` (fast distance
// queries; distances exact to within chord_tol_mm).
SegmentGrid stroke_grid(const Figure& figure, const Box& area, double chord_tol_mm);

// Feed and arc moves that move in XY below z_below.
std::vector<CanonMove> cutting_moves(const std::vector<CanonMove>& moves, double z_below);

}  // namespace mark::test
