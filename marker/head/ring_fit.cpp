#include "marker/head/ring_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mark {
namespace {

constexpr double kLowest_hz = 2000, kHighest_hz = 25000;
constexpr int kFrequencySteps = 240;  // 1 % apart over the range
constexpr double kZetas[] = {0.005, 0.01, 0.02, 0.035, 0.05, 0.08, 0.12, 0.2};

struct Trial {
  double sum = 1e300;       // squared residual left, mm²
  double amplitude = 0;     // mm: the largest corner's, at its first place
};

// The 3 × 3 system M·x = r by elimination with partial pivoting; false when singular.
bool solve3(double M[3][3], double r[3], double x[3]) {
  for (int c = 0; c < 3; ++c) {
    int p = c;
    for (int i = c + 1; i < 3; ++i)
      if (std::abs(M[i][c]) > std::abs(M[p][c])) p = i;
    if (!(std::abs(M[p][c]) > 1e-300)) return false;
    std::swap(M[c], M[p]);
    std::swap(r[c], r[p]);
    for (int i = c + 1; i < 3; ++i) {
      const double f = M[i][c] / M[c][c];
      for (int j = c; j < 3; ++j) M[i][j] -= f * M[c][j];
      r[i] -= f * r[c];
    }
  }
  for (int c = 2; c >= 0; --c) {
    double v = r[c];
    for (int j = c + 1; j < 3; ++j) v -= M[c][j] * x[j];
    x[c] = v / M[c][c];
  }
  return true;
}

// Each corner: residual ≈ c + e^{−ζωt}·(a·cos ω_d t + b·sin ω_d t), solved for (c, a, b) by the
// normal equations (three unknowns against hundreds of places: well conditioned here).
Trial evaluate(const std::vector<RingTrace>& corners, double hz, double zeta) {
  const double w = 2 * std::numbers::pi * hz, wd = w * std::sqrt(1 - zeta * zeta);
  Trial trial;
  trial.sum = 0;
  for (const RingTrace& c : corners) {
    const std::size_t n = c.t_s.size();
    double M[3][3] = {}, r[3] = {}, yy = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double t = c.t_s[k], decay = std::exp(-zeta * w * t);
      const double f[3] = {1, decay * std::cos(wd * t), decay * std::sin(wd * t)};
      const double y = c.residual_mm[k];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) M[i][j] += f[i] * f[j];
        r[i] += f[i] * y;
      }
      yy += y * y;
    }
    double x[3] = {0, 0, 0};
    double rhs[3] = {r[0], r[1], r[2]};
    double MM[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) MM[i][j] = M[i][j];
    if (!solve3(MM, rhs, x)) {  // a constant only
      trial.sum += yy - (n > 0 ? r[0] * r[0] / static_cast<double>(n) : 0);
      continue;
    }
    // Residual sum of squares: y·y − x·(Aᵀy).
    trial.sum += std::max(0.0, yy - (x[0] * r[0] + x[1] * r[1] + x[2] * r[2]));
    const double t0 = c.t_s.front();
    trial.amplitude = std::max(trial.amplitude, std::hypot(x[1], x[2]) * std::exp(-zeta * w * t0));
  }
  return trial;
}

}  // namespace

RingFit fit_ring(const std::vector<RingTrace>& corners) {
  RingFit fit;
  std::size_t places = 0;
  double before = 0;
  for (const RingTrace& c : corners) {
    if (c.t_s.size() < 10) return fit;
    double mean = 0;
    for (double r : c.residual_mm) mean += r;
    mean /= static_cast<double>(c.residual_mm.size());
    for (double r : c.residual_mm) before += (r - mean) * (r - mean);
    places += c.t_s.size();
  }
  if (places == 0) return fit;
  // The scan: every frequency at every damping.
  const double step = std::log(kHighest_hz / kLowest_hz) / kFrequencySteps;
  double best_hz = kLowest_hz, best_zeta = kZetas[0];
  Trial best;
  for (int i = 0; i <= kFrequencySteps; ++i) {
    const double hz = kLowest_hz * std::exp(step * i);
    for (double zeta : kZetas) {
      const Trial t = evaluate(corners, hz, zeta);
      if (t.sum < best.sum) best = t, best_hz = hz, best_zeta = zeta;
    }
  }
  // Golden-section refinement of the frequency between the best scan point's neighbours.
  double a = std::log(best_hz) - step, b = std::log(best_hz) + step;
  const double g = (std::sqrt(5.0) - 1) / 2;
  double u = b - g * (b - a), v = a + g * (b - a);
  double fu = evaluate(corners, std::exp(u), best_zeta).sum, fv = evaluate(corners, std::exp(v), best_zeta).sum;
  for (int k = 0; k < 30; ++k) {
    if (fu < fv) b = v, v = u, fv = fu, u = b - g * (b - a), fu = evaluate(corners, std::exp(u), best_zeta).sum;
    else a = u, u = v, fu = fv, v = a + g * (b - a), fv = evaluate(corners, std::exp(v), best_zeta).sum;
  }
  const double refined_hz = std::exp((a + b) / 2);
  const Trial refined = evaluate(corners, refined_hz, best_zeta);
  if (refined.sum < best.sum) best = refined, best_hz = refined_hz;
  const double n = static_cast<double>(places);
  fit.frequency_hz = best_hz;
  fit.zeta = best_zeta;
  fit.amplitude_um = best.amplitude * 1e3;
  fit.rms_before_um = std::sqrt(before / n) * 1e3;
  fit.rms_after_um = std::sqrt(best.sum / n) * 1e3;
  // Seen: the sinusoid takes a tenth of the residual's power away, at a frequency inside the
  // scan (not pinned to its ends) and damped less than the scan's heaviest (a ring that dies
  // within a period is no resonance a shaper is for: a residual of the servo model's own error
  // fits there).
  const bool inside = best_hz > kLowest_hz * 1.02 && best_hz < kHighest_hz / 1.02 && best_zeta < kZetas[std::size(kZetas) - 1];
  fit.seen = inside && best.sum < 0.9 * before && fit.amplitude_um > 2 * fit.rms_after_um;
  return fit;
}

}  // namespace mark
