#pragma once
// A pen: how the planner turns lit elements into commands — speeds, the tick of the locus,
// which corner strategy to use and its parameters, and the laser delay line's edge delays.
// Defaults come from the head's tracking error τ (dynamics.md §2.2 and §3.2).
#include <cstdint>
#include <optional>
#include <string_view>

namespace mark {

enum class CornerStrategy {
  blanking,  // the seed's claim: laser-off run-out, join and run-in lines at sharp corners and
             // at every stroke's start and end; the laser bit delayed by τ against the mirrors
  delays,    // the RTC model: laser-on/off delays, jump, mark and polygon delays
  none       // neither (for comparison)
};

std::string_view to_string(CornerStrategy strategy);

// Input shapers (marker/plan/input_shaper.hpp): ZV, two impulses half a period apart; ZVD,
// three over a whole period, which in theory tolerates a resonance further off (5 % of the
// ringing left at ±14 %, ZV's at ±3 %) but smooths twice as much. Measured on the simulator
// (docs/speed.md), ZV holds "high" over as wide a band and marks closer, so it is the default.
enum class ShaperKind { zv, zvd };
// "blanking", "delays" or "none"; throws InputError naming the value otherwise.
CornerStrategy parse_corner_strategy(std::string_view name);

struct Pen {
  double mark_speed_mm_s = 1000;
  double jump_speed_mm_s = 5000;
  double tick_s = 10e-6;
  CornerStrategy corner = CornerStrategy::blanking;

  // Laser delay line (every strategy): laser-on edges and laser-off edges leave the line memory
  // this much later than the coordinates they came with.
  double laser_on_delay_s = 0;
  double laser_off_delay_s = 0;

  // Scanner delays (strategy `delays`), dwells of the mirrors.
  double jump_delay_s = 0;     // after every jump (at least)
  // Variable jump delay: when > 0, a jump's delay is lengthened until the first-order model
  // says its transient has decayed to this when the laser switches on (RTC's length-dependent
  // jump delay, from the model rather than a table). 0: the fixed jump delay only.
  double jump_settle_mm = 0;
  double mark_delay_s = 0;     // after the last mark of a stroke
  double polygon_delay_s = 0;  // between two marks of a stroke, × (1 − cos φ)

  // Blanking (strategy `blanking`).
  double blank_angle_deg = 0;  // lit corners turning by more than this get blanking lines
  double run_out_mm = 0;       // the forward extension after every lit element's end
  // The backward extension before every lit element's start. Unset: sized per element by the
  // head's first-order model so that the transient left by the moves before it (run-out, join
  // or jump, the run-in's own start) has decayed to `settle_mm` when the laser switches on, and
  // never shorter than `min_run_in_mm`.
  std::optional<double> run_in_mm;
  double min_run_in_mm = 0;
  double settle_mm = 0.001;
  double join_speed_mm_s = 0;   // speed on the joining line between a run-out and a run-in
  // Blanking marks each element at the speed nearest the pen's at which it takes whole ticks,
  // so element boundaries fall on the locus's ticks. A board with its own clock
  // (plan_for_device) runs its own ticks: it marks at the pen's speed, or the host's rounding
  // would only make the board's speed words change from stroke to stroke.
  bool whole_tick_speeds = true;

  // The head's tracking error τ: sizes the automatic run-ins and variable jump delays.
  double tracking_error_s = 0;

  // Look-ahead speed planning (every corner strategy; speed_plan.hpp): each move's speed is
  // planned over the whole job ahead — at most its own speed, at most √(a·r) on a curve of
  // radius r, changing at the given rates, down to a stop wherever the path turns sharply — and
  // lit power follows the speed, so the dose per mm stays constant.
  bool lookahead = false;
  double accel_mm_s2 = 0;        // lit moves, and a laser-off move's arrival at a lit start
  double jump_accel_mm_s2 = 0;   // laser-off moves
  double curve_accel_mm_s2 = 0;  // centripetal, on every curve
  double junction_dv_mm_s = 0;   // velocity change allowed where the path turns without a stop
  // The head's acceleration limit: on a curve the tangential and centripetal accelerations
  // together, √(a_t² + a_c²), stay within it (0: no such check).
  double accel_limit_mm_s2 = 0;
  // Speed at which the laser may switch where the path runs straight on (blanking's run-ins
  // and run-outs); elsewhere, and by default, it switches at rest.
  double laser_switch_speed_mm_s = 0;
  // Lit moves go dark below this speed (0: never).
  double min_lit_speed_mm_s = 0;

  // Feed-forward (needs look-ahead): every sample is the desired beam position pre-compensated
  // by the planner's model of the head, x + lag·ẋ + inertia·ẍ (first order: lag τ; second
  // order: lag 2ζ/ωn, inertia 1/ωn²), so the beam rather than the command follows the path.
  // Both 0: off.
  double ff_lag_s = 0;
  double ff_inertia_s2 = 0;
  bool feed_forward() const { return ff_lag_s > 0 || ff_inertia_s2 > 0; }

  // Input shaping (needs look-ahead; marker/plan/input_shaper.hpp): the mirror resonance the
  // locus is shaped against, Hz (0: off), the damping ratio the shaper assumes, and its kind.
  double shaper_hz = 0;
  double shaper_zeta = 0.02;
  ShaperKind shaper = ShaperKind::zv;

  // Seconds → whole ticks of this pen (rounded to nearest).
  std::uint32_t ticks(double seconds) const;
};

// The multiples of v·τ and of τ the defaults are built from. The blanking values were chosen
// with the simulated scanner (`cps --speed V --run-out K --settle E --join-speed J`, and
// tests/marker/blanking_sim_test.cpp): a run-out of exactly v·τ is what the τ-delayed laser-off
// needs (0.8 leaves a lit tail, more only costs time); run-ins sized by the settling model to
// 1 µm; the join at jump speed (3 % faster than at marking speed for the same quality).
struct PenRules {
  // RTC starting rule (SCANLAB manuals, §6.1 of every head manual).
  double laser_on = 0.6, laser_off = 1.2, jump = 2.0, mark = 1.0, polygon = 0.5;
  // Variable jump delay of the delays strategy: the jump transient left at laser on, µm
  // (0 = the fixed 2τ jump delay only).
  double jump_settle_um = 1.0;
  // Blanking: extension lengths as multiples of v·τ (the run-in's is its minimum; unset run_in
  // sizes it by the settling model), the transient allowed at laser on, the join at jump speed.
  std::optional<double> run_in;
  double min_run_in = 1.0, run_out = 1.0, settle_um = 1.0;
  // Corners turning less than this stay lit (the lag's corner cut there is below a few µm at
  // marking speeds where the rest of the figure keeps its quality).
  double blank_angle_deg = 8.0;

  // Look-ahead speed planning, and feed-forward of the head model (which implies look-ahead).
  // With feed-forward the beam has no lag left to wait for: the laser delays, scanner delays
  // and settling run-ins become zero, and blanking's run-in and run-out are sized for
  // acceleration instead — multiples run_in / run_out of the distance v²/(2a) the mirrors need
  // to reach the marking speed. The laser still switches at rest (it switches on a tick: at
  // speed its edge would wander by v·tick), so under feed-forward blanking's lines only add
  // travel — cps shows it; the corner strategy that gains is none, stopping lit at corners.
  bool lookahead = false;
  bool feed_forward = false;
  // Rates as shares of the head's acceleration limit: lit moves (and arrivals at a lit start),
  // laser-off moves, centripetal on curves; the velocity step allowed at a turn taken at speed.
  double accel_share = 0.5, jump_accel_share = 0.8, curve_accel_share = 0.5;
  double junction_dv_mm_s = 100;
  // Lit moves dark below this share of the marking speed (Command::min_lit_speed_mm_s).
  double min_lit_speed_share = 0.03;
};

// What the planner knows of a head: its ramp lag (τ, or 2ζ/ωn), the second-order term of its
// inverse (1/ωn²; 0 for a first-order model) and its per-axis acceleration limit.
struct HeadDynamics {
  double lag_s = 0;
  double inertia_s2 = 0;
  double max_accel_mm_s2 = 0;
};

// A pen for a head, every parameter from the rules and the head's dynamics.
Pen default_pen(CornerStrategy strategy, const HeadDynamics& head, double mark_speed_mm_s,
                double jump_speed_mm_s, double tick_s = 10e-6, const PenRules& rules = {});
// The same for a head known only by its tracking error (no look-ahead or feed-forward).
Pen default_pen(CornerStrategy strategy, double tracking_error_s, double mark_speed_mm_s,
                double jump_speed_mm_s, double tick_s = 10e-6, const PenRules& rules = {});

}  // namespace mark
