#include "marker/gravure/tuning_filter.hpp"

#include <cmath>
#include <numbers>

#include "marker/limits/gravure_settings.hpp"

namespace mark {

MatchedZ matched_z(double f, double d, double tick_s) {
  const double wt = tick_s * 2 * std::numbers::pi * f;
  const double decay = std::exp(-wt * d);
  // The patent's formula for d < 1; its continuation through d = 1 (cos → cosh) beyond.
  const double c1 = d < 1 ? 2 * std::cos(wt * std::sqrt(1 - d * d)) * decay
                          : 2 * std::cosh(wt * std::sqrt(d * d - 1)) * decay;
  return {c1, decay * decay};
}

std::string_view to_string(SectionKind kind) {
  switch (kind) {
    case SectionKind::notch: return "notch";
    case SectionKind::emphasis: return "emphasis";
    case SectionKind::antiresonance: return "antiresonance";
  }
  return "?";
}

FilterSection notch_section(double freq_hz, double damping, double depth_db) {
  return {SectionKind::notch, freq_hz, damping, freq_hz, damping * std::pow(10.0, depth_db / 20)};
}

FilterSection emphasis_section(double freq_hz, double damping, double corner_hz, double corner_damping) {
  return {SectionKind::emphasis, freq_hz, damping, corner_hz, corner_damping};
}

void validate(const FilterSection& s, std::size_t index) {
  const std::string at = "filter section " + std::to_string(index + 1) + " (" + std::string(to_string(s.kind)) + ")";
  check_range(at + " zero frequency", s.zero_hz, kFilterFrequencyBounds.range());
  check_range(at + " pole frequency", s.pole_hz, kFilterFrequencyBounds.range());
  check_range(at + " zero damping", s.zero_damping, kZeroDampingBounds.range());
  check_range(at + " pole damping", s.pole_damping, kPoleDampingBounds.range());
}

BiquadCoefficients design(const FilterSection& s, double tick_s) {
  const MatchedZ z = matched_z(s.zero_hz, s.zero_damping, tick_s);
  const MatchedZ p = matched_z(s.pole_hz, s.pole_damping, tick_s);
  const double k = (1 - p.c1 + p.c2) / (1 - z.c1 + z.c2);
  return {k, -k * z.c1, k * z.c2, -p.c1, p.c2};
}

std::complex<double> response(const BiquadCoefficients& c, double freq_hz, double tick_s) {
  const std::complex<double> z1 = std::polar(1.0, -2 * std::numbers::pi * freq_hz * tick_s);
  return (c.b0 + z1 * (c.b1 + z1 * c.b2)) / (1.0 + z1 * (c.a1 + z1 * c.a2));
}

std::complex<double> response(const FilterBank& bank, double freq_hz, double tick_s) {
  std::complex<double> h = bank.gain;
  for (const FilterSection& s : bank.sections) h *= response(design(s, tick_s), freq_hz, tick_s);
  return h;
}

}  // namespace mark
