#pragma once
// Test support: distances between the interpreter's moves and the Figure's strokes.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "fonts/element.hpp"
#include "marker/layout/figure.hpp"
#include "rs274.hpp"

namespace mark::test {

// Elements with their bounds in a hashed grid of `cell_mm` cells, queried by distance from a
// point: a query looks only at the cells within `beyond` (160 rows of text against the moves
// that cut them: 93 s with every element's box tested per point, 2026-11-28).
class NearSet {
 public:
  explicit NearSet(double cell_mm = 0.5) : cell_(cell_mm) {}
  void add(const Element& e);
  // Distance to the nearest element, or `beyond` when none is within `beyond`.
  double distance(const Point& p, double beyond) const;
  std::size_t size() const { return elements_.size(); }

 private:
  double cell_;
  std::vector<Element> elements_;
  std::vector<Box> boxes_;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> wide_;  // elements over too many cells: tested on every query
  std::int64_t cell_of(double v) const;
  static std::int64_t key(std::int64_t i, std::int64_t j) { return (i << 32) ^ (j & 0xffffffff); }
  void consider(std::uint32_t k, const Point& p, double& best) const;
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
