#include "marker/peen/move_cost.hpp"

#include <algorithm>

namespace mark {
namespace {

std::vector<double> axis_table(std::int64_t max_steps, const AxisLimits& axis) {
  std::vector<double> t(static_cast<std::size_t>(max_steps) + 1);
  for (std::int64_t k = 0; k <= max_steps; ++k)
    t[static_cast<std::size_t>(k)] = axis_time_s(static_cast<double>(k) / axis.steps_per_mm, axis);
  return t;
}

}  // namespace

MoveCost::MoveCost(const std::vector<StepPoint>& points, const GantryConfig& gantry)
    : points_(points), gantry_(gantry) {
  std::int64_t x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  if (!points.empty()) x0 = x1 = points[0].x, y0 = y1 = points[0].y;
  for (const StepPoint& p : points) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  // Up to a million steps per axis (8 MB): 110 mm at 9000 steps/mm. Beyond, no tables.
  constexpr std::int64_t kMaxTable = 1 << 20;
  if (x1 - x0 > kMaxTable || y1 - y0 > kMaxTable) {
    direct_ = true;
    return;
  }
  x_s_ = axis_table(x1 - x0, gantry.x);
  y_s_ = axis_table(y1 - y0, gantry.y);
}

double MoveCost::lower_bound(double mm) const {
  if (mm <= 0) return 0;
  const double tx = axis_time_s(mm, gantry_.x), ty = axis_time_s(mm, gantry_.y);
  return tx < ty ? tx : ty;
}

}  // namespace mark
