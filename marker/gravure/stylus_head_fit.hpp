#pragma once
// Fitting the head model to a measured response (the automatic tuning of FIG. 8, block 236):
// the resonances' frequencies and dampings are found by Levenberg–Marquardt (Eigen's
// unsupported NonLinearOptimization module) on the complex response, each point weighted by the
// inverse of its uncertainty — its measurement noise (from the sine fit), or 1 % of |H| where
// that is larger — so the small high-frequency gains count as much as the peaks and noisy points
// count less. For given frequencies and dampings the modes' gains are linear and are solved
// exactly inside every evaluation (variable projection), which leaves the search only 2
// parameters a mode. The model is the held (DAC) head of driver/sim/stylus_head_model.hpp, the
// system the test really measures, seen as each point saw it: from the position, the velocity
// over jω, or their fused mix (point_response()).
//
// Start values: the peaks of |H| with at least 3 dB prominence among the points measured with a
// signal-to-noise ratio of 10 or more (the FIG. 9 peaks), at most 4; a fit that ends on a
// non-physical mode (a peak that was noise) is retried without the least prominent peak.
#include <span>

#include "driver/sim/stylus_head_model.hpp"
#include "marker/gravure/stylus_head_response.hpp"

namespace mark {

struct HeadFit {
  StylusHeadModel model;             // modes ascending in frequency
  double rms_relative_error = 0;     // |H_model − H| / |H|, rms over the points with SNR ≥ 10
  int evaluations = 0;
};

// modes = 0: as many as there are prominent peaks. Throws InputError when the response has no
// peak, too few points, or the fit ends on a non-physical model (gain ≤ 0, damping outside 0 .. 1).
HeadFit fit_head(std::span<const ResponsePoint> response, int modes = 0);

}  // namespace mark
