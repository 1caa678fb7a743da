#include "marker/gravure/head_design.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <unsupported/Eigen/Polynomials>

#include "base/error.hpp"
#include "marker/limits/gravure_settings.hpp"

namespace mark {
namespace {

using Poly = std::vector<double>;  // ascending powers of s

Poly multiply(const Poly& a, const Poly& b) {
  Poly c(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

}  // namespace

std::vector<ZeroPair> antiresonances(const StylusHeadModel& head) {
  validate(head);
  const std::size_t n = head.modes.size();
  if (n < 2) return {};
  // Work in s / ω0 with ω0 = 2π·1 kHz so the coefficients stay near 1.
  const double w0 = 2 * std::numbers::pi * 1000;
  Poly num(2 * n - 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double wi = 2 * std::numbers::pi * head.modes[i].freq_hz / w0;
    Poly term{head.modes[i].gain * wi * wi};
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const double wj = 2 * std::numbers::pi * head.modes[j].freq_hz / w0;
      term = multiply(term, {wj * wj, 2 * head.modes[j].damping * wj, 1.0});
    }
    for (std::size_t k = 0; k < term.size(); ++k) num[k] += term[k];
  }
  Eigen::VectorXd coeffs = Eigen::Map<Eigen::VectorXd>(num.data(), static_cast<Eigen::Index>(num.size()));
  Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(coeffs);
  std::vector<std::complex<double>> upper, real;
  for (const std::complex<double>& r : solver.roots()) {
    if (r.real() >= 0)
      throw InputError("stylus head " + describe(head) +
                       ": the modal sum has a zero in the right half-plane; it cannot be inverted");
    if (std::abs(r.imag()) < 1e-9 * std::abs(r))
      real.push_back(r);
    else if (r.imag() > 0)
      upper.push_back(r);
  }
  std::vector<ZeroPair> pairs;
  for (const auto& r : upper) {
    const double w = std::abs(r);
    pairs.push_back({w * w0 / (2 * std::numbers::pi), -r.real() / w});
  }
  // Real zeros come in twos (the degree is even and complex ones pair up): join neighbours.
  std::sort(real.begin(), real.end(), [](auto a, auto b) { return a.real() < b.real(); });
  for (std::size_t i = 0; i + 1 < real.size(); i += 2) {
    const double a = -real[i].real(), b = -real[i + 1].real();
    const double w = std::sqrt(a * b);
    pairs.push_back({w * w0 / (2 * std::numbers::pi), (a + b) / (2 * w)});
  }
  std::sort(pairs.begin(), pairs.end(), [](auto a, auto b) { return a.freq_hz < b.freq_hz; });
  return pairs;
}

FilterBank design_for_head(const StylusHeadModel& head, const TargetResponse& t) {
  validate(head);
  check_range("target corner frequency", t.corner_hz, kTargetCorner.range());
  check_range("target damping", t.damping, {0.3, 2, ""});
  check_range("replacement damping", t.replacement_damping, {0.3, 2, ""});
  std::vector<StylusMode> modes = head.modes;
  std::sort(modes.begin(), modes.end(), [](auto a, auto b) { return a.freq_hz < b.freq_hz; });
  const std::vector<ZeroPair> zeros = antiresonances(head);
  const double dr = t.replacement_damping;

  FilterBank bank;
  bank.gain = 1 / head.static_gain();
  for (const StylusMode& m : modes)
    bank.sections.push_back({SectionKind::notch, m.freq_hz, m.damping, m.freq_hz, dr});
  for (std::size_t k = 0; k < zeros.size(); ++k)
    bank.sections.push_back({SectionKind::antiresonance, modes[k].freq_hz, dr, zeros[k].freq_hz, zeros[k].damping});
  bank.sections.push_back({SectionKind::emphasis, modes.back().freq_hz, dr, t.corner_hz, t.damping});
  return bank;
}

double latency_samples(const FilterBank& bank, const StylusHeadModel& head) {
  // Group delay at DC from the phase slope between two low frequencies.
  const double f1 = 5, f2 = 10;
  auto phase = [&](double f) { return std::arg(response(bank, f) * held_response(head, f)); };
  const double delay_s = -(phase(f2) - phase(f1)) / (2 * std::numbers::pi * (f2 - f1));
  return delay_s / kStylusTick_s;
}

Flatness predicted_flatness(const FilterBank& bank, const StylusHeadModel& head, double max_hz) {
  const double dc = std::abs(response(bank, 1) * held_response(head, 1));
  Flatness fl{0, 0};
  for (double f = 10; f <= max_hz; f += 10) {
    const double db = 20 * std::log10(std::abs(response(bank, f) * held_response(head, f)) / dc);
    fl.min_db = std::min(fl.min_db, db);
    fl.max_db = std::max(fl.max_db, db);
  }
  return fl;
}

}  // namespace mark
