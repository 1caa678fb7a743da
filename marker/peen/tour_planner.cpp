#include "marker/peen/tour_planner.hpp"

namespace mark {

PeenPlan plan_optimized(const DotText& text, const Point& home_mm, const GantryConfig& gantry,
                        const TourOptions& options) {
  gantry.validate();
  PeenPlan plan;
  plan.planner = "optimized";
  plan.home_mm = home_mm;
  // Point 0 is home, point i + 1 is dot i; all in motor steps, as the gantry will stand.
  std::vector<StepPoint> points;
  points.reserve(text.dots.size() + 1);
  points.push_back(to_steps(home_mm, gantry));
  for (const Dot& d : text.dots) points.push_back(to_steps(d.pos_mm, gantry));
  const MoveCost cost(points, gantry);
  std::vector<std::size_t> tour = nearest_neighbour_tour(cost, 0);
  improve_tour(tour, cost, 0, options);
  plan.stops.reserve(text.dots.size());
  for (std::size_t k = 1; k < tour.size(); ++k) {
    const std::size_t dot = tour[k] - 1;
    plan.stops.push_back({text.dots[dot].pos_mm, dot});
  }
  return plan;
}

}  // namespace mark
