#pragma once
// The electromechanical engraving head as a linear system: the stylus position (µm) is the sum
// of second-order resonances driven by the amplifier's drive (µm of static travel),
//
//   H(s) = Σ_i g_i ω_i² / (s² + 2 ζ_i ω_i s + ω_i²),   ω_i = 2π f_i,   Σ g_i = 1,
//
// the modal form of a collocated actuator: the armature's torsion mode near 1.8 kHz carries most
// of the travel and a bending mode near 5.5 kHz the rest (US 6,007,230, FIG. 9: "first and
// second resonances typically occur around 1800 and 5500" Hz). Between two modes of the same
// sign the sum has a lightly damped antiresonance, as measured heads do.
//
// The drive reaches the head through a DAC that holds each sample for one stylus tick (zero-
// order hold). discretise() gives each mode's exact hold-equivalent state update, which both the
// simulated head (driver/sim/sim_stylus_head.hpp) and the tuner's fit (marker/gravure/) use, so the
// model the tuner fits is the system it measures, not an approximation of it.
#include <array>
#include <complex>
#include <string>
#include <vector>

namespace mark {

// The stylus clock of the seed: the tuning processor runs 200 000 times a second.
inline constexpr double kStylusRate_hz = 200000;
inline constexpr double kStylusTick_s = 1.0 / kStylusRate_hz;

struct StylusMode {
  double freq_hz = 1800;  // undamped natural frequency
  double damping = 0.06;  // ζ, 0 < ζ < 1
  double gain = 0.8;      // share of the static travel (the gains of a head sum to 1)
};

struct StylusHeadModel {
  std::vector<StylusMode> modes;
  // Static gain: µm of travel per µm of drive at DC.
  double static_gain() const;
};

// A typical head: 1.8 kHz (ζ 0.06, 80 % of the travel) and 5.5 kHz (ζ 0.04, 20 %).
StylusHeadModel default_stylus_head();

// Throws std::invalid_argument naming the mode and the value when a mode is not a damped
// resonance below the stylus Nyquist frequency (0 < f < 50 kHz, 0 < ζ < 1, gain > 0).
void validate(const StylusHeadModel& head);

// One mode held for one tick T: state s = (x µm, v µm/s) after the tick from the state before
// and the drive u held during it,  s' = Φ s + (I − Φ)(g u, 0).
struct ModeStep {
  std::array<double, 4> phi;  // row-major 2×2
  double gain;
};
ModeStep discretise(const StylusMode& mode, double tick_s = kStylusTick_s);

// Frequency response of the held head at f (Hz): the sampled position after each tick over the
// drive held during it, H(e^{jωT}) = Σ_i g_i [1 0] (I − Φ_i z⁻¹)⁻¹ (I − Φ_i)(1, 0)ᵀ.
std::complex<double> held_response(const StylusHeadModel& head, double freq_hz,
                                   double tick_s = kStylusTick_s);

// The same for the sampled velocity (µm/s per µm of drive), [0 1] in place of [1 0]. Not jω times
// held_response: the held drive's images (1/T ± f) move the stylus between the samples, and their
// velocity, sampled, folds onto f (2 % of the response at 16 kHz on the typical head).
std::complex<double> held_velocity_response(const StylusHeadModel& head, double freq_hz,
                                            double tick_s = kStylusTick_s);

// "1800 Hz ζ 0.060 g 0.80, 5500 Hz ..." for messages.
std::string describe(const StylusHeadModel& head);

}  // namespace mark
