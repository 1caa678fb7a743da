#pragma once
// Fits the servo's ramp lag from a picture of the lag test pattern (lag_pattern.hpp): a camera
// photograph or a flatbed scan, at a known pixel size, the pattern upright (x to the right,
// y up; a picture turned by up to 1.5° still fits: each line is followed across the
// picture, and the offset the turn adds between neighbouring rows is the same at every speed).
//
//   1. Marks are told from the surface by Otsu's threshold; the side with fewer pixels is the
//      marks (dark marks on a light part, or light on a dark one).
//   2. The marks' bounding box places the pattern: its edges are where lines start from rest
//      (sharp) or the lines' sides, never a lagging end.
//   3. Each line's centre is found at 30 % and 70 % of its block's length, where every line is
//      marked (the centroids of the ink's runs across a five-pixel strip, in order); along the
//      straight line through the two (the darkest pixel within 0.15 mm of it), the far end is
//      where the marks cross the threshold, found from outside inwards and interpolated between
//      pixels.
//   4. Per speed, the far ends of the forward and the backward line lie L − 2·v·τ + c apart;
//      a straight line through those distances over the speeds gives τ per axis.
//   5. Where the pattern has corners, they give the servo's order and ζ at that τ
//      (corner_fit.hpp), the lines' tilt taking out the picture's turn.
#include <string>
#include <vector>

#include "marker/head/corner_fit.hpp"
#include "marker/head/head_profile.hpp"
#include "marker/head/lag_pattern.hpp"
#include "marker/image/gray_image.hpp"

namespace mark {

struct LagPairFigure {
  int axis = 0;
  double speed_mm_s = 0;
  double ends_apart_mm = 0;  // far end of the forward line − far end of the backward one
  double residual_um = 0;    // from the fitted straight line
};

struct LagFit {
  double tau_x_s = 0, tau_y_s = 0;
  double tau_s = 0;          // their mean: the profile's τ
  double rms_um = 0;         // of the residuals
  std::vector<LagPairFigure> pairs;
  CornerFit corners;         // empty when the pattern has none
};

// Throws InputError naming `where` (the picture's file name) when the picture does not show the
// pattern at this pixel size: no marks, a bounding box not the pattern's size within 5 %, or a
// line whose end cannot be found.
LagFit fit_lag_from_image(const GrayImage& picture, double pixel_mm, const LagPattern& pattern,
                          const std::string& where);

// The head profile a picture gives (`"source": "image"`): `base`'s limits, which a picture does
// not show, with the lines' ramp lag and the corners' model — second order at their (ωn, ζ)
// when they choose it — and the corners' residuals (without corners: the lines', first order).
HeadProfile picture_profile(HeadProfile base, const LagFit& fit);

}  // namespace mark
