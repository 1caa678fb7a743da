#pragma once
// Fits a mirror resonance to what the servo model leaves of the lag test pattern's corners.
//
// At a corner marked at speed the stopping axis's shaft decelerates at once, and a mirror that
// twists against its shaft (a lightly damped mode of a few kHz to 20 kHz) rings after it: the
// mark's centre across the second leg swings about the servo model's path, a damped sinusoid in
// the time since the corner. corner_fit.cpp hands over each corner's residuals against the
// chosen servo model, with the time at each measured place (from the model's own run); the fit
// shares the frequency and damping across the corners, each corner with its own amplitude,
// phase and offset (linear least squares at every trial frequency and damping: a log scan of
// 2–25 kHz and of ζ 0.005–0.2, then golden-section refinement of the frequency).
//
// A resonance is reported only when the damped sinusoid takes at least a tenth of the residual's
// power away, its amplitude is twice what is left, its frequency is inside the scan and
// its damping below the scan's heaviest; otherwise none was seen, which on a head without one is
// the answer (and on a head with a weak one means it rings less than the picture resolves).
#include <optional>
#include <vector>

namespace mark {

// One corner's residual across its second leg: time since the corner (s) and the centre off the
// servo model (mm), place by place.
struct RingTrace {
  std::vector<double> t_s;
  std::vector<double> residual_mm;
};

struct RingFit {
  bool seen = false;
  double frequency_hz = 0;     // the best fit's (reported even when not seen)
  double zeta = 0;
  double amplitude_um = 0;     // the largest corner's fitted amplitude at the first place measured
  double rms_before_um = 0;    // the residual without and with the damped sinusoid
  double rms_after_um = 0;
};

RingFit fit_ring(const std::vector<RingTrace>& corners);

}  // namespace mark
