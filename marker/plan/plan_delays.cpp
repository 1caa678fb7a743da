// Strategy `delays`, the RTC model (galvo.md §3.1, dynamics.md §2): after every jump the mirrors
// settle for the jump delay; between two marks of a stroke they wait the polygon delay scaled by
// 1 − cos φ of the turn angle φ with the laser still on; after the stroke's last mark the mark
// delay lets them reach the end before the next jump. The laser-on and laser-off delays are not
// commands: the laser delay line applies them to the laser bit downstream of the line memory.
//
// Variable jump delay (RTC's length-dependent jump delay): a jump's delay is at least the pen's
// jump delay, and longer when the first-order model says the jump's transient would otherwise
// still exceed jump_settle_mm when the laser switches on. The mark delay is never shorter than
// the laser-off delay, so no jump starts with the laser still on.
#include <algorithm>
#include <cmath>

#include "marker/plan/plan.hpp"
#include "marker/plan/plan_builder.hpp"
#include "marker/plan/settle_model.hpp"

namespace mark {

namespace {

double jump_delay_s(const Pen& pen, const Point& v_before, const Command& jump) {
  if (!(pen.jump_settle_mm > 0) || !(pen.tracking_error_s > 0)) return pen.jump_delay_s;
  const Point v_jump = jump.speed_mm_s * jump.path.tangent_at(0.0);
  const double amplitude = transient_mm(v_before, v_jump, jump.length_mm() / jump.speed_mm_s,
                                        Point(0, 0), pen.tracking_error_s);
  const double needed = settle_time_s(amplitude, pen.jump_settle_mm, pen.tracking_error_s) -
                        pen.laser_on_delay_s;
  return std::max(pen.jump_delay_s, needed);
}

}  // namespace

void plan_stroke_delays(PlanBuilder& b, const Stroke& stroke) {
  const Pen& pen = b.pen;
  const Point v_before = b.velocity();
  if (b.jump_to(stroke.start())) b.dwell(pen.ticks(jump_delay_s(pen, v_before, b.out.back())), false);
  for (std::size_t i = 0; i < stroke.elements.size(); ++i) {
    if (i > 0) {
      const double phi = turn_angle_rad(stroke.elements[i - 1], stroke.elements[i]);
      b.dwell(pen.ticks(pen.polygon_delay_s * (1.0 - std::cos(phi))), true);
    }
    b.move(b.mark(stroke.elements[i], pen.mark_speed_mm_s, CommandRole::stroke));
  }
  // The next jump waits at least until the delayed laser-off has happened: with SCANLAB's
  // starting values (mark τ, laser-off 1.2τ) the laser would otherwise still burn for 0.2τ while
  // the mirrors accelerate into the jump — a ~20 µm streak at 1 mm text on the simulator.
  b.dwell(std::max(pen.ticks(pen.mark_delay_s), pen.ticks(pen.laser_off_delay_s)), false);
}

}  // namespace mark
