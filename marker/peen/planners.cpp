#include "marker/peen/planners.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/error.hpp"
#include "marker/peen/block_snake.hpp"
#include "marker/peen/tour_planner.hpp"
#include "marker/peen/window_snake.hpp"

namespace mark {

const char* planner_name(PlannerKind kind) {
  switch (kind) {
    case PlannerKind::snake: return "snake";
    case PlannerKind::block: return "block";
    case PlannerKind::optimized: return "optimized";
  }
  return "?";
}

std::optional<PlannerKind> parse_planner(std::string_view name) {
  for (PlannerKind k : kAllPlanners)
    if (name == planner_name(k)) return k;
  return std::nullopt;
}

Box tight_window(const DotText& text) { return text.bounds(); }

Box centred_window(double width_mm, double height_mm) {
  if (!(width_mm >= 0) || !(height_mm >= 0) || !std::isfinite(width_mm) || !std::isfinite(height_mm))
    throw InputError("marking window " + std::to_string(width_mm) + " x " +
                     std::to_string(height_mm) + " mm: sides must be non-negative lengths");
  Box b;
  b.add(Point(-width_mm / 2, -height_mm / 2));
  b.add(Point(width_mm / 2, height_mm / 2));
  return b;
}

Point home_of(const Box& window) { return {window.min.x(), window.max.y()}; }

void require_in_window(const DotText& text, const Box& window) {
  if (text.dots.empty()) throw InputError("the text has no dots to strike");
  const Box b = text.bounds();
  // Rounding in the layout must not turn a dot on the edge into an error.
  constexpr double kTol = 1e-6;
  if (window.contains(b, kTol)) return;
  const double over = std::max({window.min.x() - b.min.x(), b.max.x() - window.max.x(),
                                window.min.y() - b.min.y(), b.max.y() - window.max.y()});
  char msg[256];
  std::snprintf(msg, sizeof msg,
                "dots span x %.3f..%.3f, y %.3f..%.3f mm and leave the marking window "
                "x %.3f..%.3f, y %.3f..%.3f mm by %.3f mm",
                b.min.x(), b.max.x(), b.min.y(), b.max.y(), window.min.x(), window.max.x(),
                window.min.y(), window.max.y(), over);
  throw InputError(msg);
}

PeenPlan plan_peen(const DotText& text, PlannerKind kind, const PeenSetup& setup) {
  require_in_window(text, setup.window);
  const Point home = home_of(setup.window);
  switch (kind) {
    case PlannerKind::snake: return plan_window_snake(text, setup.window);
    case PlannerKind::block: return plan_block_snake(text, setup.window, setup.block_one_axis_at_a_time);
    case PlannerKind::optimized: {
      TourOptions tour;
      tour.progress = setup.progress;
      return plan_optimized(text, home, setup.gantry, tour);
    }
  }
  throw InputError("unknown planner");
}

}  // namespace mark
