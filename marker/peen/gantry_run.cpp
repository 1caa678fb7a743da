#include "marker/peen/gantry_run.hpp"

#include <cmath>

namespace mark {
namespace {

// Counts sign changes of one axis' motion, ignoring moves where that axis stands still.
class ReversalCounter {
 public:
  std::size_t add(std::int64_t delta) {
    if (delta == 0) return 0;
    const int sign = delta > 0 ? 1 : -1;
    const bool reversed = last_ != 0 && sign != last_;
    last_ = sign;
    return reversed ? 1 : 0;
  }

 private:
  int last_ = 0;
};

}  // namespace

GantryReport run_plan(const PeenPlan& plan, const GantryConfig& gantry, bool keep_log) {
  gantry.validate();
  GantryReport r;
  ReversalCounter rx, ry;
  StepPoint at = to_steps(plan.home_mm, gantry);
  auto go = [&](const StepPoint& to, std::optional<std::size_t> strike) {
    if (!(to == at)) {
      GantryMove m{at, to, axis_profile(to.x - at.x, gantry.x), axis_profile(to.y - at.y, gantry.y),
                   0, strike};
      m.duration_s = std::max(m.x.duration_s(), m.y.duration_s());
      r.move_s += m.duration_s;
      r.travel_mm += std::hypot(m.x.distance_mm, m.y.distance_mm);
      r.reversals += rx.add(m.x.steps) + ry.add(m.y.steps);
      ++r.moves;
      if (keep_log) r.log.push_back(m);
      at = to;
    } else if (keep_log && strike) {
      // A strike without a move (the head is already there) still belongs in the log.
      r.log.push_back({at, at, {}, {}, 0, strike});
    }
    if (strike) {
      ++r.strikes;
      r.strike_s += gantry.strike_s;
    }
  };
  for (const PlanStop& s : plan.stops) go(to_steps(s.pos_mm, gantry), s.dot);
  go(to_steps(plan.home_mm, gantry), std::nullopt);
  r.total_s = r.move_s + r.strike_s;
  return r;
}

}  // namespace mark
