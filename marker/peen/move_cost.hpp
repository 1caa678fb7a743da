#pragma once
// The cost the optimised planner minimises: the gantry's time to move between two points
// (already quantised to motor steps), exactly as the simulator times it. Each axis' time depends
// only on its step count, so both are tabulated once for every distance the points can be apart:
// a cost is then two table reads and a max (computed directly when the points span more steps
// than a table should hold).
#include <vector>

#include "marker/peen/gantry.hpp"

namespace mark {

class MoveCost {
 public:
  MoveCost(const std::vector<StepPoint>& points, const GantryConfig& gantry);

  double operator()(std::size_t a, std::size_t b) const {
    const StepPoint& p = points_[a];
    const StepPoint& q = points_[b];
    if (direct_) return move_time_s(p, q, gantry_);
    const double tx = x_s_[static_cast<std::size_t>(p.x > q.x ? p.x - q.x : q.x - p.x)];
    const double ty = y_s_[static_cast<std::size_t>(p.y > q.y ? p.y - q.y : q.y - p.y)];
    return tx > ty ? tx : ty;
  }
  // A lower bound of the time to any point at least `mm` away along one axis or the other.
  double lower_bound(double mm) const;
  std::size_t size() const { return points_.size(); }
  const std::vector<StepPoint>& points() const { return points_; }
  const GantryConfig& gantry() const { return gantry_; }

 private:
  const std::vector<StepPoint>& points_;
  const GantryConfig& gantry_;
  std::vector<double> x_s_;  // time of a move of k steps along x
  std::vector<double> y_s_;
  bool direct_ = false;      // too many steps apart to tabulate: compute each time
};

}  // namespace mark
