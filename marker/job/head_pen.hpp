#pragma once
// The default pen for a head: every delay and extension from its tracking error τ, the jump
// speed from its positioning limit.
#include "driver/head_model.hpp"
#include "marker/plan/pen.hpp"

namespace mark {

// Jumps run at this share of the head's positioning-speed limit: at the limit itself the
// speed clamp of the axes would add its own lag on top of τ and the settling after a jump
// would no longer follow the first-order model the delays and run-ins are built on.
inline constexpr double kJumpSpeedShare = 0.5;

Pen pen_for_head(const HeadModel& head, CornerStrategy strategy, double mark_speed_mm_s,
                 double tick_s = 10e-6, const PenRules& rules = {});

}  // namespace mark
