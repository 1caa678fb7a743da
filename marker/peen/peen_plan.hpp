#pragma once
// A needle path: the head leaves its home position, stops at each stop in order (striking the dot
// there, or only turning), and returns home. Positions in the field frame, mm.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "fonts/box.hpp"

namespace mark {

struct PlanStop {
  Point pos_mm{0, 0};
  std::optional<std::size_t> dot;  // index into DotText::dots struck here; empty for a turn point
};

struct PeenPlan {
  std::string planner;  // "snake", "block" or "optimized"
  Point home_mm{0, 0};
  std::vector<PlanStop> stops;
};

}  // namespace mark
