#pragma once
// Visiting order for things that are entered at one point and left at another — strokes of a
// letter, letters of a text, pocket rings — so that the travel between them (rapid moves on a
// mill, jumps on a galvo) stays short. Nearest neighbour with reversal, then 2-opt (reverse a run
// of reversible items) and relocation (move one item elsewhere, optionally reversed) until no
// move shortens the travel. The travel is open: it starts at `start` and ends at the last exit.
#include <cstddef>
#include <vector>

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
std::vector<VisitStep> plan_visit_order(const std::vector<VisitItem>& items, const Point& start);

}  // namespace mark
