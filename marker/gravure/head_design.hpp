#pragma once
// Filter coefficients for a known (or fitted) head: the bank that makes filters × head equal a
// flat target — a well-damped second-order roll-off far above the band the cells use — so the
// stylus follows the toolpath with flat gain to 10 kHz (the seed's FIG. 11).
//
// For a head of n resonances, H(s) = K·N(s) / Π D_i(s) (N: the n−1 antiresonance pairs of the
// modal sum), the bank is, every pair through the seed's C1/C2:
//
//   notch i          zeros (f_i, ζ_i)             poles (f_i, d_r)          i = 1..n
//   antiresonance k  zeros (f_k, d_r)             poles (antiresonance k)   k = 1..n−1
//   emphasis         zeros (f_n, d_r)             poles (f_t, d_t)
//
// and the gain 1/K. The well-damped replacement pairs (f_i, d_r) cancel between stages, so the
// product is exactly Π D_i / (N·D_t): the head's poles and zeros are cancelled and the target
// D_t is left. Each stage on its own is a familiar shape — the notches are FIG. 12's notches
// (depth 20·log10(d_r/ζ_i)), the emphasis stage boosts above the highest resonance up to the
// target corner — and can be shown to and adjusted by an operator.
#include <string>
#include <vector>

#include "driver/sim/stylus_head_model.hpp"
#include "marker/gravure/tuning_filter.hpp"

namespace mark {

struct TargetResponse {
  double corner_hz = 20000;     // f_t: −3 dB of the flat target (−0.26 dB at 10 kHz)
  double damping = 0.7071;      // d_t: Butterworth
  double replacement_damping = 0.5;  // d_r
};

// Throws InputError for an impossible target (corner outside 11 .. 45 kHz, dampings outside
// 0.3 .. 2) or std::invalid_argument from validate(head).
FilterBank design_for_head(const StylusHeadModel& head, const TargetResponse& target = {});

// The head's antiresonances (zeros of the modal sum) as (frequency, damping) pairs, ascending;
// a pair of real zeros has damping ≥ 1.
struct ZeroPair {
  double freq_hz;
  double damping;
};
std::vector<ZeroPair> antiresonances(const StylusHeadModel& head);

// Delay from the toolpath to the stylus at low frequencies (group delay at DC) of bank × head,
// in stylus samples: the synchronisation advance that puts each cell where it belongs.
double latency_samples(const FilterBank& bank, const StylusHeadModel& head);

// Gain of bank × held head relative to DC, minimum and maximum over 0 .. max_hz (dB).
struct Flatness {
  double min_db = 0;
  double max_db = 0;
};
Flatness predicted_flatness(const FilterBank& bank, const StylusHeadModel& head, double max_hz = 10000);

}  // namespace mark
