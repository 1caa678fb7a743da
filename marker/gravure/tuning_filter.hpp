#pragma once
// The tuning filters of US 6,007,230 (FIG. 7, 11, 12): biquad IIR sections whose coefficients
// come from user parameters — a frequency and a damping — through the patent's formulas
//
//   C1 = 2·cos(T·2π·f·√(1−d²))·e^(−T·2π·f·d),   C2 = (e^(−T·2π·f·d))²,   T = 5 µs,
//
// which are the coefficients of 1 − C1 z⁻¹ + C2 z⁻², the pole pair of a mass–spring–damper
// (f, d) mapped by z = e^(sT) (matched z; ../shared/reference/dynamics.md §6.2). For d ≥ 1 the
// same mapping of the two real roots gives C1 = 2·cosh(T·2π·f·√(d²−1))·e^(−T·2π·f·d).
//
// A section has a zero pair (f_z, d_z) and a pole pair (f_p, d_p), each through C1/C2, and is
// scaled to unity gain at DC:
//
//   H(z) = K (1 − C1z z⁻¹ + C2z z⁻²) / (1 − C1p z⁻¹ + C2p z⁻²),  K = (1 − C1p + C2p)/(1 − C1z + C2z)
//
// - notch: zeros on a head resonance, poles at the same frequency with more damping; the notch
//   depth is 20·log10(d_p/d_z) dB (FIG. 12's frequency and notch depth);
// - emphasis: zeros at the emphasis frequency, poles at a higher corner: the gain rises above
//   the emphasis frequency by up to (f_p/f_z)² (the emphasis filter 56);
// - antiresonance: zeros well damped, poles on the head's antiresonance, refilling the dip that
//   lies between two resonances of a real head.
#include <complex>
#include <string>
#include <string_view>
#include <vector>

#include "driver/sim/stylus_head_model.hpp"

namespace mark {

struct MatchedZ {
  double c1 = 0;
  double c2 = 0;
};

// The patent's coefficient pair for (f, d) at the stylus tick. f in Hz, 0 ≤ f < f_s/2, d ≥ 0.
MatchedZ matched_z(double freq_hz, double damping, double tick_s = kStylusTick_s);

enum class SectionKind { notch, emphasis, antiresonance };
std::string_view to_string(SectionKind kind);

struct FilterSection {
  SectionKind kind = SectionKind::notch;
  double zero_hz = 1800;
  double zero_damping = 0.06;
  double pole_hz = 1800;
  double pole_damping = 0.5;
};

// The classic notch of FIG. 12: centred on f, cancelling a resonance of damping d, depth in dB.
FilterSection notch_section(double freq_hz, double damping, double depth_db);
// The emphasis filter: flat below freq_hz, rising above it up to the corner (f, d).
FilterSection emphasis_section(double freq_hz, double damping, double corner_hz, double corner_damping);

// Throws InputError naming the section and the parameter when a frequency is outside
// (0, 50 kHz), a zero damping outside 0 .. 10 or a pole damping outside (0, 10].
void validate(const FilterSection& section, std::size_t index);

struct BiquadCoefficients {
  double b0 = 1, b1 = 0, b2 = 0;  // numerator
  double a1 = 0, a2 = 0;          // denominator 1 + a1 z⁻¹ + a2 z⁻²
};

BiquadCoefficients design(const FilterSection& section, double tick_s = kStylusTick_s);

// A cascade of sections and an overall gain (1 / the head's static gain when designed for a head).
struct FilterBank {
  std::vector<FilterSection> sections;
  double gain = 1;
  bool empty() const { return sections.empty() && gain == 1; }
};

// Designed response at f (Hz).
std::complex<double> response(const BiquadCoefficients& c, double freq_hz, double tick_s = kStylusTick_s);
std::complex<double> response(const FilterBank& bank, double freq_hz, double tick_s = kStylusTick_s);

}  // namespace mark
