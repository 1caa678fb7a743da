#pragma once
// A closed tour through points minimising the total gantry move time: nearest neighbour from the
// start point, then 2-opt and Or-opt (segments of 1–3 points moved elsewhere, either way round)
// over each point's cheapest neighbours, with don't-look bits, until no move improves the tour.
// Deterministic: the same points always give the same tour.
#include <cstddef>
#include <vector>

#include "marker/peen/move_cost.hpp"

namespace mark {

struct TourOptions {
  std::size_t neighbours = 10;  // candidate list length per point
};

// The visiting order of all points, starting with `start`.
std::vector<std::size_t> nearest_neighbour_tour(const MoveCost& cost, std::size_t start);
// Improves `tour` in place (any rotation; returned starting with `start`).
void improve_tour(std::vector<std::size_t>& tour, const MoveCost& cost, std::size_t start,
                  const TourOptions& options = {});
double tour_time_s(const std::vector<std::size_t>& tour, const MoveCost& cost);

}  // namespace mark
