#pragma once
// A uniform grid over the tour's points (in mm) for the two spatial queries the optimised planner
// needs: the k cheapest neighbours of every point, and the cheapest point not yet in the tour.
#include <cstddef>
#include <vector>

#include "marker/peen/move_cost.hpp"

namespace mark {

class PointGrid {
 public:
  // Cells sized for about one point each over the points' bounding box.
  explicit PointGrid(const MoveCost& cost);

  // For each point, up to k other points by increasing move time (those found within the first
  // rings of cells that hold k points, plus one ring).
  std::vector<std::vector<std::size_t>> neighbour_lists(std::size_t k) const;

  // Removes a point from the set still to visit.
  void visit(std::size_t point);
  // The unvisited point with the least move time from `from`; size() when none is left.
  std::size_t nearest_unvisited(std::size_t from) const;

 private:
  std::size_t cell_of(std::size_t point) const;
  long cell_x(double x_mm) const;
  long cell_y(double y_mm) const;

  const MoveCost& cost_;
  std::vector<Point> mm_;
  double x0_ = 0, y0_ = 0, cell_mm_ = 1;
  long nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::size_t>> cells_;  // unvisited points per cell
  std::vector<std::size_t> slot_;               // index of each point inside its cell's vector
  std::vector<std::size_t> unvisited_;          // all unvisited points (for the far fallback)
  std::vector<std::size_t> unvisited_slot_;
};

}  // namespace mark
