// Strategy `blanking`, the seed's claim (EP 0657850, claim 3): where two lit elements that are
// drawn one after the other meet at a corner turning by more than the pen's blank angle, three
// laser-off lines are inserted — a run-out extending the first element forward along its end
// tangent, a run-in extending the second backward along its start tangent, and a line joining the
// two. Every stroke also starts with a run-in and ends with a run-out. So the mirrors reach each
// lit element already moving at marking speed along it, and leave it the same way; with the laser
// bit delayed by τ (the seed's delay means) the burn starts and stops on the end points.
//
// Each lit element is marked at the speed nearest the pen's at which it takes a whole number of
// ticks, and its run-in and run-out run at that same speed for a whole number of ticks: then
// every element boundary falls on a tick and the beam's speed does not change where the laser
// switches, which is what the τ delay assumes.
//
// Lengths: the run-out is v·τ (the τ-delayed laser-off happens exactly as the lagging beam
// crosses the end point; anything longer only costs time). The joining line runs at jump speed,
// and each run-in is as long as the head's first-order model says the transient of the moves
// before it needs to decay to the pen's settle_mm by the time the laser switches on (see
// settle_model.hpp) — unless the pen fixes the run-in length.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "marker/plan/plan.hpp"
#include "marker/plan/plan_builder.hpp"
#include "marker/plan/settle_model.hpp"

namespace mark {
namespace {

double whole_tick_speed(double len, double speed_mm_s, double tick_s) {
  const double ticks = std::max(1.0, std::round(len / (speed_mm_s * tick_s)));
  return len / (ticks * tick_s);
}

}  // namespace

void plan_stroke_blanking(PlanBuilder& b, const Stroke& stroke) {
  const Pen& pen = b.pen;
  const double limit_rad = pen.blank_angle_deg * std::numbers::pi / 180.0;
  const double step_mm = pen.mark_speed_mm_s * pen.tick_s;
  const double out_ticks = std::ceil(pen.run_out_mm / step_mm - 1e-9);
  const double join_speed = pen.join_speed_mm_s > 0 ? pen.join_speed_mm_s : pen.jump_speed_mm_s;
  const std::vector<Element>& els = stroke.elements;
  bool continues_smoothly = false;  // the previous element runs into this one without blanking

  for (std::size_t i = 0; i < els.size(); ++i) {
    const Element& e = els[i];
    Command mark = b.mark(e, pen.mark_speed_mm_s, CommandRole::stroke);
    const double v = mark.speed_mm_s = pen.whole_tick_speeds
                                           ? whole_tick_speed(mark.length, pen.mark_speed_mm_s, pen.tick_s)
                                           : pen.mark_speed_mm_s;
    const bool starts_run = i == 0 || !continues_smoothly;
    if (starts_run) {
      const Point dir = e.tangent_at(0.0);
      const double want =
          pen.run_in_mm ? *pen.run_in_mm
                        : settled_run_in_mm({b.at, b.velocity(), e.start(), dir, v,
                                             // a stroke is reached by a jump, a corner's
                                             // run-in by the joining line
                                             i == 0 ? pen.jump_speed_mm_s : join_speed,
                                             pen.tracking_error_s, pen.settle_mm,
                                             pen.min_run_in_mm});
      // Whole ticks at the element's speed, rounded up so the settling is not cut short.
      const double len = std::ceil(want / (v * pen.tick_s) - 1e-9) * v * pen.tick_s;
      const Point from = e.start() - len * dir;
      if (i == 0) {
        b.jump_to(from);
      } else if ((from - b.at).norm() > kJoinTolerance_mm) {
        b.move(Command::mark(Element::line(b.at, from, false), join_speed,
                             CommandRole::blank_join));
      }
      if (len > 0) b.move(Command::mark(Element::line(from, e.start(), false), v,
                                        CommandRole::run_in));
    }
    b.move(mark);
    continues_smoothly = i + 1 < els.size() && turn_angle_rad(e, els[i + 1]) <= limit_rad;
    const bool ends_run = !continues_smoothly;
    if (ends_run && out_ticks > 0) {
      const double len = out_ticks * v * pen.tick_s;
      b.move(Command::mark(Element::line(e.end(), e.end() + len * e.tangent_at(1.0), false), v,
                           CommandRole::run_out));
    }
  }
}

}  // namespace mark
