#include "marker/peen/window_snake.hpp"

#include <algorithm>
#include <cmath>

namespace mark {

PeenPlan plan_window_snake(const DotText& text, const Box& window) {
  PeenPlan plan;
  plan.planner = "snake";
  const double top = window.max.y(), left = window.min.x(), right = window.max.x();
  plan.home_mm = Point(left, top);
  const double pitch = text.pitch_mm;
  // The row grid is the dots' own, extended to the window's edges: the first row is the highest
  // grid line inside the window.
  const double ref = text.dots.empty() ? top : text.bounds().max.y();
  const double first = ref + std::floor((top - ref) / pitch + 1e-9) * pitch;
  const std::size_t rows =
      static_cast<std::size_t>(std::floor((first - window.min.y()) / pitch + 1e-9)) + 1;

  std::vector<std::vector<std::size_t>> by_row(rows);
  for (std::size_t i = 0; i < text.dots.size(); ++i) {
    const double k = std::round((first - text.dots[i].pos_mm.y()) / pitch);
    by_row[static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(rows - 1)))].push_back(i);
  }

  for (std::size_t k = 0; k < rows; ++k) {
    const double y = first - static_cast<double>(k) * pitch;
    const bool rightward = k % 2 == 0;
    std::vector<std::size_t>& row = by_row[k];
    std::sort(row.begin(), row.end(), [&](std::size_t a, std::size_t b) {
      const double xa = text.dots[a].pos_mm.x(), xb = text.dots[b].pos_mm.x();
      return rightward ? xa < xb : xa > xb;
    });
    // One step down at the edge where the last row ended, the sweep, the turn at the far edge.
    plan.stops.push_back({Point(rightward ? left : right, y), std::nullopt});
    for (std::size_t i : row) plan.stops.push_back({text.dots[i].pos_mm, i});
    plan.stops.push_back({Point(rightward ? right : left, y), std::nullopt});
  }
  return plan;
}

}  // namespace mark
