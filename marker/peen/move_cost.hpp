#pragma once
// The cost the optimised planner minimises: the gantry's time to move between two points
// (already quantised to motor steps), exactly as the simulator times it.
#include <vector>

#include "marker/peen/gantry.hpp"

namespace mark {

class MoveCost {
 public:
  MoveCost(const std::vector<StepPoint>& points, const GantryConfig& gantry)
      : points_(points), gantry_(gantry) {}

  double operator()(std::size_t a, std::size_t b) const {
    return move_time_s(points_[a], points_[b], gantry_);
  }
  // A lower bound of the time to any point at least `mm` away along one axis or the other.
  double lower_bound(double mm) const {
    if (mm <= 0) return 0;
    const double tx = axis_time_s(mm, gantry_.x), ty = axis_time_s(mm, gantry_.y);
    return tx < ty ? tx : ty;
  }
  std::size_t size() const { return points_.size(); }
  const std::vector<StepPoint>& points() const { return points_; }
  const GantryConfig& gantry() const { return gantry_; }

 private:
  const std::vector<StepPoint>& points_;
  const GantryConfig& gantry_;
};

}  // namespace mark
