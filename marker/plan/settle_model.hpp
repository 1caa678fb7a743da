#pragma once
// How long the mirrors need to settle, from the head's first-order model (ẋ = (c − x)/τ).
//
// Measure the beam against where it would be at steady state, x − (c − τ·ċ): that error jumps
// by τ·Δv wherever the commanded velocity changes by Δv and then decays as e^(−t/τ). A move of
// duration T between two others changes the velocity twice, so right after it the error is
//   A = τ·|(v_move − v_before)·e^(−T/τ) + (v_after − v_move)|,
// and it falls to ε after τ·ln(A/ε). Both corner strategies size their waiting with this: the
// blanking run-ins (long enough that the laser switches on — τ after the run-in's end — with
// the transient below ε) and the delays strategy's variable jump delay (RTC's length-dependent
// jump delay, here from the model instead of a table).
#include "fonts/box.hpp"

namespace mark {

// A, in mm: the transient right after a move at velocity v_move lasting t_move_s, entered from
// v_before and left into v_after (mm/s vectors).
double transient_mm(const Point& v_before, const Point& v_move, double t_move_s,
                    const Point& v_after, double tau_s);

// Time for a transient of amplitude_mm to decay to settle_mm (0 if it already has).
double settle_time_s(double amplitude_mm, double settle_mm, double tau_s);

struct RunInRequest {
  Point from;           // where the mirrors are commanded now (end of the previous move)
  Point velocity_mm_s;  // commanded velocity of the previous move at its end (0 at rest)
  Point start;          // the lit element's start
  Point direction;      // its unit start tangent
  double speed_mm_s;    // marking speed of the element and its run-in
  double join_speed_mm_s;
  double tau_s;
  double settle_mm;     // ε
  double min_length_mm;
};

// Blanking run-in length (mm, not yet rounded to ticks): the shortest k·v·τ (k ≥ the pen's
// least) after which the transient A the join into the run-in leaves has decayed to ε by the time
// the τ-delayed laser switches on: A·e^−(k+1) ≤ ε. A depends on k, and not monotonically: a
// longer run-in moves its start back towards where the mirrors are (a shorter, slower-settling
// join), past them and behind (a reversing join). A fixed-point iteration of k = ln(A/ε) − 1 could
// stop where the laser comes on unsettled — a raster hatch's next line ahead on the same row lit
// 50 µm early (issue 23) — so k is searched upward.
double settled_run_in_mm(const RunInRequest& r);

}  // namespace mark
