#pragma once
// The default marking speed when none is given (`marker mark --speed auto`): the fastest speed,
// up to a cap, at which the head's lag shrinks the tightest curve of the figure by no more than
// a few micrometres. On a first-order head of tracking error τ a curve of radius r traversed at
// speed v is drawn (v·τ)²/(2r) inside its true path; the quality figures count a stroke covered
// when the lit beam passes within 10 µm of it, so 8 µm keeps every arc covered with margin.
// Measured on the simulated SL10 head (blanking): "ABC" centred is "high" at the speed this
// gives for 1, 2, 3 and 5 mm (516, 730, 894, 1000 mm/s), "poor" at 1000 mm/s for 1 and 2 mm.
#include "driver/sim/head_model.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

inline constexpr double kAutoSpeedCap_mm_s = 1000;
inline constexpr double kAutoSpeedShrink_mm = 0.008;

// Smallest radius of curvature of the figure's lit arcs and ellipse arcs (an ellipse's is
// b²/a); infinity when it has none.
double tightest_radius_mm(const Figure& figure);

// min(cap, √(2·r·shrink)/τ) for the tightest radius r of the figure.
double auto_mark_speed_mm_s(const Figure& figure, const HeadModel& head);

}  // namespace mark
