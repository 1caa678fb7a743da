// Strategy `delays`, the RTC model (galvo.md §3.1, dynamics.md §2): after every jump the mirrors
// settle for the jump delay; between two marks of a stroke they wait the polygon delay scaled by
// 1 − cos φ of the turn angle φ with the laser still on; after the stroke's last mark the mark
// delay lets them reach the end before the next jump. The laser-on and laser-off delays are not
// commands: the laser delay line applies them to the laser bit downstream of the line memory.
#include <cmath>

#include "marker/plan/plan.hpp"
#include "marker/plan/plan_builder.hpp"

namespace mark {

void plan_stroke_delays(PlanBuilder& b, const Stroke& stroke) {
  const Pen& pen = b.pen;
  if (b.jump_to(stroke.start())) b.dwell(pen.ticks(pen.jump_delay_s), false);
  for (std::size_t i = 0; i < stroke.elements.size(); ++i) {
    if (i > 0) {
      const double phi = turn_angle_rad(stroke.elements[i - 1], stroke.elements[i]);
      b.dwell(pen.ticks(pen.polygon_delay_s * (1.0 - std::cos(phi))), true);
    }
    b.move(Command::mark(stroke.elements[i], pen.mark_speed_mm_s, CommandRole::stroke));
  }
  b.dwell(pen.ticks(pen.mark_delay_s), false);
}

}  // namespace mark
