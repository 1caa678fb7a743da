#include "marker/job/head_pen.hpp"

namespace mark {

Pen pen_for_head(const HeadModel& head, CornerStrategy strategy, double mark_speed_mm_s,
                 double tick_s, const PenRules& rules) {
  return default_pen(strategy, head.tau_s, mark_speed_mm_s, kJumpSpeedShare * head.max_speed_mm_s,
                     tick_s, rules);
}

}  // namespace mark
