#pragma once
// Shared state of the corner strategies while they append commands for one plan: where the
// mirrors are and the pen. One strategy per file (plan_plain.cpp, plan_delays.cpp,
// plan_blanking.cpp).
#include <vector>

#include "marker/plan/command.hpp"
#include "marker/plan/pen.hpp"
#include "marker/plan/stroke.hpp"

namespace mark {

struct PlanBuilder {
  const Pen& pen;
  std::vector<Command>& out;
  Point at;
  // Ellipse lengths by shape (axes, start and sweep; position and rotation do not change a
  // length): an ellipse's length is a quadrature, and a serial number repeats its digits.
  std::vector<std::pair<EllipticalArc, double>> ellipse_lengths;

  // A mark command for `e` at `speed`, its length from the memo where it can be.
  Command mark(const Element& e, double speed_mm_s, CommandRole role);

  // A jump from the current position, unless already there. Returns whether it jumped.
  bool jump_to(const Point& target);
  // Commanded velocity at the end of the last command (zero at rest or after a dwell), mm/s.
  Point velocity() const;
  void move(const Command& c) {
    out.push_back(c);
    at = c.end();
  }
  void dwell(std::uint32_t ticks, bool laser) {
    if (ticks > 0) out.push_back(Command::dwell(at, ticks, laser));
  }
};

void plan_stroke_plain(PlanBuilder& b, const Stroke& stroke);
void plan_stroke_delays(PlanBuilder& b, const Stroke& stroke);
void plan_stroke_blanking(PlanBuilder& b, const Stroke& stroke);

}  // namespace mark
