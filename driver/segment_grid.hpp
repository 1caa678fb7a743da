#pragma once
// A uniform grid over many short segments for local queries: the nearest segment to a point and
// "is any segment within r". The quality figures run these for every lit point and every
// sample along the intended strokes, so they must not scan all segments.
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "driver/vec2.hpp"

namespace mark {

class SegmentGrid {
 public:
  struct Segment {
    Vec2 a, b;
  };
  struct Nearest {
    double distance = std::numeric_limits<double>::infinity();
    std::uint32_t segment = 0;  // index in insertion order
    double t = 0;               // unclamped parameter of the foot point along a→b
  };

  explicit SegmentGrid(double cell_mm);
  void add(Vec2 a, Vec2 b);
  std::size_t size() const { return segments_.size(); }
  const Segment& segment(std::uint32_t i) const { return segments_[i]; }

  // Nearest segment, searching at most max_rings rings of cells around p; distance is infinite
  // if nothing was found that close (the caller then asks a coarser grid).
  Nearest nearest(Vec2 p, int max_rings) const;
  // True if some segment passes within radius of p.
  bool any_within(Vec2 p, double radius) const;

 private:
  static std::uint64_t key(std::int64_t cx, std::int64_t cy);
  std::int64_t cell(double v) const;
  void consider(std::uint32_t i, Vec2 p, Nearest& best) const;

  double cell_mm_;
  std::vector<Segment> segments_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

// Distance from p to segment a→b, and the unclamped foot parameter t.
double point_segment_distance(Vec2 p, Vec2 a, Vec2 b, double* t_out = nullptr);

}  // namespace mark
