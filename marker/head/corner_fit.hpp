#pragma once
// Fits the servo's order and damping from the corners of the lag test pattern (lag_pattern.hpp),
// in a picture the lag fit has already placed: ζ (and ωn = 2ζ/τ at the lines' ramp lag τ), which
// a line's far end cannot show — the lines give 2ζ/ωn only.
//
// At a right-angle corner marked at speed v the axis that stops approaches the corner's line
// from behind (a first-order head: v·τ·e^{−t/τ}, never past it) or swings past it and back (an
// underdamped second-order head), while the other axis runs the second leg. The mark's centre
// across the second leg, row by row along it, is that axis's path as a function of the other's:
//   1. the first leg's centre across it (at its middle) places the corner along the second leg;
//   2. from 0.15 mm past the corner to 0.3 mm before the second leg's lagging end, each row's
//      ink centroid across the leg (within 0.35 mm of the leg's settled centre), corrected for
//      the picture's turn (the long lines' tilt);
//   3. each model — first order at τ, second order at (ζ, 2ζ/τ) — runs the same corner
//      (exact steps of the loop, 1 µs) and is compared row by row; the settled leg's place in
//      the picture is the one free offset per corner;
//   4. ζ minimises the squared residuals over every corner (a log scan over 0.1 … 10, then a
//      golden-section refinement); the second order is chosen when its RMS residual is under
//      half the first order's and ζ < 3, the rule `head identify` applies to step responses;
//   5. what the chosen model leaves is searched for a mirror resonance ringing after the corner
//      (ring_fit.hpp).
#include <string>
#include <vector>

#include "driver/vec2.hpp"
#include "marker/head/lag_pattern.hpp"
#include "marker/head/pattern_marks.hpp"
#include "marker/head/ring_fit.hpp"

namespace mark {

struct CornerFigure {
  int axis = 0;               // the axis that stops at the corner
  double speed_mm_s = 0;
  int rows = 0;               // places measured along the second leg
  double overshoot_um = 0;    // the largest measured excursion past the settled second leg
  double rms_first_um = 0;    // residuals at the fitted first- and second-order models
  double rms_second_um = 0;
};

struct CornerFit {
  bool second_order = false;  // the model the corners choose
  double zeta = 0;            // the best second-order fit (reported even when not chosen)
  double omega_n_rad_s = 0;
  double rms_first_um = 0, rms_second_um = 0;
  std::vector<CornerFigure> corners;
  // A mirror resonance in what the chosen model leaves (ring_fit.hpp); `ring.seen` false: none.
  RingFit ring;
};

// The picture as the lag fit placed it: field mm ↔ pixels through the marks' box, and the
// long lines' tilt in the picture (x lines' dY/dX and y lines' dX/dY, y upwards).
struct PlacedPicture {
  const PatternMarks& marks;
  double pixel_mm = 0;
  Vec2 lo, hi;                // the pattern's commanded extent
  int box_x0 = 0, box_y0 = 0; // the marks' box: its left column and top row
  double turn_x = 0, turn_y = 0;
};

// Throws InputError naming `where` when a corner's legs are not where the pattern puts them.
CornerFit fit_corners(const PlacedPicture& picture, const LagPattern& pattern, double tau_x_s, double tau_y_s,
                      const std::string& where);

}  // namespace mark
