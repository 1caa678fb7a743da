#pragma once
// Executes a needle path on the simulated gantry: quantises every stop to motor steps, times each
// move with the trapezoidal model and adds the strike time per dot.
#include <cstddef>
#include <optional>
#include <vector>

#include "marker/peen/gantry.hpp"
#include "marker/peen/peen_plan.hpp"

namespace mark {

// One move between two stops (zero-length moves are not moves and are not listed).
struct GantryMove {
  StepPoint from;
  StepPoint to;
  AxisProfile x;
  AxisProfile y;
  double duration_s = 0;               // the slower axis
  std::optional<std::size_t> strike;   // dot struck on arrival
};

struct GantryReport {
  double total_s = 0;   // moves + strikes
  double move_s = 0;
  double strike_s = 0;
  double travel_mm = 0;          // straight-line length of all moves
  std::size_t strikes = 0;
  std::size_t moves = 0;
  std::size_t reversals = 0;     // changes of direction on the X axis plus on the Y axis
  std::vector<GantryMove> log;   // every move, when asked for
};

GantryReport run_plan(const PeenPlan& plan, const GantryConfig& gantry, bool keep_log = false);

}  // namespace mark
