#pragma once
// Visiting order for things that are entered at one point and left at another — the strokes of
// a whole text, letters, pocket rings, hatch lines — so that the travel between them (rapid moves
// on a mill, jumps on a galvo) stays short. Nearest neighbour with reversal (an R-tree of the
// entry points not yet used), then 2-opt (reverse a run of reversible items) and relocation
// (move one item elsewhere, optionally reversed) within a window of 24 positions around each
// item, looked at again only near a change, until no move shortens the travel: O(N log N) in the
// number of items.
// The travel is open: it starts at `start` and ends at the last exit.
#include <cstddef>
#include <vector>

#include "base/progress.hpp"
#include "fonts/box.hpp"

namespace mark {

struct VisitItem {
  Point entry{0, 0};
  Point exit{0, 0};
  // A reversible item may be run backwards instead, entering at entry_reversed and leaving at
  // exit_reversed (for a plain stroke: its end and its start).
  bool reversible = false;
  Point entry_reversed{0, 0};
  Point exit_reversed{0, 0};

  // A stroke from a to b that may be run either way.
  static VisitItem stroke(const Point& a, const Point& b) { return {a, b, true, b, a}; }
  // An item with a fixed direction.
  static VisitItem fixed(const Point& in, const Point& out) { return {in, out, false, in, out}; }
};

struct VisitStep {
  std::size_t item = 0;
  bool reversed = false;
};

// Total travel from `start` through the items in the given order.
double travel_length(const std::vector<VisitItem>& items, const std::vector<VisitStep>& order,
                     const Point& start);

// A short visiting order (never longer than the items in their given order, unreversed).
// `progress` is told how far it got and may stop it (throws Interrupted).
std::vector<VisitStep> plan_visit_order(const std::vector<VisitItem>& items, const Point& start,
                                        const Progress& progress = Progress::none());

}  // namespace mark
