#pragma once
// Look-ahead speed planning, grbl's planner applied to a whole job: every move gets an entry and
// an exit speed and the rates between them (command.hpp), so the beam's speed and acceleration
// stay within what the head can follow — which is what lets feed-forward put the beam exactly
// on the path.
//
//   1. Limits per move: its own speed; on an arc or ellipse √(a_c·r) at its smallest radius of
//      curvature r (the centripetal acceleration v²/r stays within a_c).
//   2. Limits per junction: zero at the job's start and end, at every dwell and wherever the
//      laser switches (the laser bit changes on a tick, so at speed v its edge would fall
//      anywhere within v·tick: at rest it falls on the point) — except where the path runs
//      straight on, up to pen.laser_switch_speed_mm_s (default 0); where the path
//      turns by φ, the speed at which the velocity jumps by at most Δv (2·v·sin(φ/2) ≤ Δv):
//      junction_dv, and no more than the head's acceleration headroom over one tick allows
//      (the step happens between two samples) — a stop at any real corner, full speed where
//      elements join tangentially.
//   3. Backward pass (from the end): every junction speed low enough to slow down to the next
//      one over the move between them; forward pass (from the start): low enough to be reached
//      from the previous one. The job is compiled whole before it runs, so the window is the
//      whole job — grbl replans a ring of 16 blocks as they arrive; the result is the same or
//      better (no assumed stop at the window's end).
//
// Rates: on a curve the centripetal acceleration at the move's top speed and the tangential rate
// share the head's limit (pen.accel_limit_mm_s2): √(a_t² + a_c²) stays within it. Lit moves use
// pen.accel_mm_s2; laser-off moves speed up at pen.jump_accel_mm_s2 and
// arrive at a lit start at pen.accel_mm_s2 (a gentle arrival leaves the smallest transient
// where the laser comes on when the model is off), elsewhere at jump_accel. Lit moves get
// full_power_speed_mm_s = the fastest lit cruise speed of the job, so every lit sample's power
// is speed / that speed.
#include <vector>

#include "marker/plan/command.hpp"
#include "marker/plan/pen.hpp"

namespace mark {

// Plans every move of `commands` in place. The pen's rates must be positive.
void plan_speeds(std::vector<Command>& commands, const Pen& pen);

// Smallest radius of curvature along a move's element (infinite for a line).
double min_radius_mm(const Element& e);

}  // namespace mark
