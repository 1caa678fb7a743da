#pragma once
// A closed tour through points minimising the total gantry move time: nearest neighbour from the
// start point, then 2-opt and Or-opt (segments of 1–3 points moved elsewhere, either way round)
// over each point's cheapest neighbours, with don't-look bits, until no move improves the tour;
// then iterated local search (local double-bridge kicks). Deterministic: the same points always
// give the same tour.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "marker/peen/move_cost.hpp"
#include "base/progress.hpp"

namespace mark {

struct TourOptions {
  std::size_t neighbours = 10;       // candidate list length per point
  // Iterated local search: double-bridge kicks per point, at most max_kicks in all. Small texts
  // (a serial number) gain a few per cent from them; for hundreds of characters the first local
  // search is within a per cent of what more kicks find, so the cap keeps planning fast.
  std::size_t kicks_per_point = 8;
  std::size_t max_kicks = 2000;
  std::size_t kick_span = 50;        // tour positions a kick spans at most
  std::uint64_t seed = 0x5eed;       // the kicks' random sequence (fixed: plans are repeatable)
  // Told how far the search got, between moves and kicks; may stop it (throws Interrupted).
  const Progress* progress = &Progress::none();
};

// The visiting order of all points, starting with `start`.
std::vector<std::size_t> nearest_neighbour_tour(const MoveCost& cost, std::size_t start);
// Improves `tour` in place (any rotation; returned starting with `start`).
void improve_tour(std::vector<std::size_t>& tour, const MoveCost& cost, std::size_t start,
                  const TourOptions& options = {});
double tour_time_s(const std::vector<std::size_t>& tour, const MoveCost& cost);

}  // namespace mark
