// Strategy `none`: jump to each stroke and mark its elements back to back — no delays, no
// blanking. What a naive controller does; kept as the baseline the other strategies beat.
#include "marker/plan/plan_builder.hpp"

namespace mark {

void plan_stroke_plain(PlanBuilder& b, const Stroke& stroke) {
  b.jump_to(stroke.start());
  for (const Element& e : stroke.elements)
    b.move(b.mark(e, b.pen.mark_speed_mm_s, CommandRole::stroke));
}

}  // namespace mark
