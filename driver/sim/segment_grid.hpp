#pragma once
// A uniform grid over many short segments for local queries: the nearest segment to a point and
// "is any segment within r". The quality figures run these for every lit point and every
// sample along the intended strokes, so they must not scan all segments. Dense cells over the
// segments' bounds in compressed rows (one offset per cell, no hashing); the cell grows if the
// bounds would need more than max_cells cells.
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "driver/vec2.hpp"

namespace mark {

struct Segment {
  Vec2 a, b;
};

class SegmentGrid {
 public:
  struct Nearest {
    double distance = std::numeric_limits<double>::infinity();
    std::uint32_t segment = 0;  // index into the segments given
    double t = 0;               // unclamped parameter of the foot point along a→b
  };
  static constexpr std::size_t max_cells = std::size_t{1} << 22;

  SegmentGrid(std::vector<Segment> segments, double cell_mm);
  // Grids of several cell sizes over the same segments share them (a long text's intended
  // strokes are millions of segments).
  SegmentGrid(std::shared_ptr<const std::vector<Segment>> segments, double cell_mm);
  std::size_t size() const { return segments_.size(); }
  const Segment& segment(std::uint32_t i) const { return segments_[i]; }
  double cell_mm() const { return cell_mm_; }

  // Nearest segment, searching at most max_rings rings of cells around p; distance is infinite
  // if nothing was found that close (the caller then asks a coarser grid) or the grid is empty.
  // Only segments with indices in [first, last] count (all by default): the quality figures
  // measure a lit run against the one stroke it marks, whose segments are such a range.
  Nearest nearest(Vec2 p, int max_rings, std::uint32_t first = 0,
                  std::uint32_t last = std::numeric_limits<std::uint32_t>::max()) const;
  // True if some segment passes within radius of p.
  bool any_within(Vec2 p, double radius) const;

 private:
  std::int64_t cell_x(double x) const;
  std::int64_t cell_y(double y) const;
  struct Query {
    Vec2 p;
    std::uint32_t first, last;
  };
  void scan_cell(std::int64_t x, std::int64_t y, const Query& q, Nearest& best,
                 double& best_d2) const;

  std::shared_ptr<const std::vector<Segment>> owner_;
  std::span<const Segment> segments_;  // *owner_, which a move or copy of the grid leaves in place
  double cell_mm_;
  Vec2 origin_{0, 0};
  std::int64_t nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> start_;  // per cell: first index into items_ (size nx·ny + 1)
  std::vector<std::uint32_t> items_;  // segment indices, grouped by cell
};

// Distance from p to segment a→b, and the unclamped foot parameter t.
double point_segment_distance(Vec2 p, Vec2 a, Vec2 b, double* t_out = nullptr);

}  // namespace mark
