#pragma once
// The default pen for a head: every delay, extension and rate from the planner's model of the
// head (a head profile: identified by `marker head identify`, or the datasheet's figures), the
// jump speed from its positioning limit.
#include "driver/sim/head_model.hpp"
#include "marker/head/head_profile.hpp"
#include "marker/limits/setting.hpp"
#include "marker/plan/pen.hpp"

namespace mark {

// Jumps run at this share of the head's positioning-speed limit: at the limit itself the
// speed clamp of the axes would add its own lag on top of τ and the settling after a jump
// would no longer follow the first-order model the delays and run-ins are built on.
inline constexpr double kJumpSpeedShare = 0.5;

// The ranges of the pen settings that depend on the head, as the command line and job files
// check them: a speed setting (marking, jump, join speed) at most the head's positioning limit,
// the tick at most 20 % of its τ ("0.001 to 19200 mm/s (head SL10's positioning limit)").
Range head_speed_range(const Quantity& speed, const HeadModel& head);
Range head_tick_range(const HeadModel& head);

// The planner's view of a profile: lag, inverse-filter term, acceleration limit.
HeadDynamics dynamics_of(const HeadProfile& profile);

Pen pen_for_profile(const HeadProfile& profile, CornerStrategy strategy, double mark_speed_mm_s,
                    double tick_s = 10e-6, const PenRules& rules = {});
// pen_for_profile with the head's datasheet profile.
Pen pen_for_head(const HeadModel& head, CornerStrategy strategy, double mark_speed_mm_s,
                 double tick_s = 10e-6, const PenRules& rules = {});

}  // namespace mark
