#include "marker/plan/input_shaper.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "base/error.hpp"

namespace mark {

ShaperKind parse_shaper_kind(std::string_view name) {
  if (name == "zv") return ShaperKind::zv;
  if (name == "zvd") return ShaperKind::zvd;
  throw InputError("--shaper " + std::string(name) + ": unknown shaper (allowed: zv, zvd)");
}

std::string_view to_string(ShaperKind kind) { return kind == ShaperKind::zv ? "zv" : "zvd"; }

InputShaper design_input_shaper(const Pen& pen) {
  InputShaper s;
  s.lag_s = pen.ff_lag_s;
  s.inertia_s2 = pen.ff_inertia_s2;
  if (!(pen.shaper_hz > 0)) return s;
  // Impulses half a damped period apart, amplitudes 1 : K (ZV) or 1 : 2K : K² (ZVD), where K is
  // the decay of the ringing over that half period.
  const double zeta = pen.shaper_zeta;
  const double root = std::sqrt(1 - zeta * zeta);
  const double K = std::exp(-zeta * std::numbers::pi / root);
  const double half_period_ticks = 0.5 / (pen.shaper_hz * root) / pen.tick_s;
  std::vector<double> amplitude = pen.shaper == ShaperKind::zv ? std::vector<double>{1, K}
                                                               : std::vector<double>{1, 2 * K, K * K};
  double sum = 0;
  for (double a : amplitude) sum += a;
  const double last = half_period_ticks * static_cast<double>(amplitude.size() - 1);
  s.taps.assign(static_cast<std::size_t>(std::floor(last)) + 2, 0.0);
  for (std::size_t i = 0; i < amplitude.size(); ++i) {
    const double at = half_period_ticks * static_cast<double>(i);
    const auto n = static_cast<std::size_t>(std::floor(at));
    const double frac = at - static_cast<double>(n);
    s.taps[n] += (1 - frac) * amplitude[i] / sum;
    s.taps[n + 1] += frac * amplitude[i] / sum;
  }
  while (s.taps.size() > 1 && s.taps.back() == 0) s.taps.pop_back();
  double mean = 0, second = 0;
  for (std::size_t j = 0; j < s.taps.size(); ++j) {
    mean += s.taps[j] * static_cast<double>(j);
    second += s.taps[j] * static_cast<double>(j * j);
  }
  const double variance = (second - mean * mean) * pen.tick_s * pen.tick_s;
  s.delay_ticks = static_cast<std::uint32_t>(std::lround(mean));
  // The shaped command is, to second order, x(t − mean) + σ²/2·ẍ. For it to be the feed-forward
  // command Q of the path `delay_ticks` later, x(t) = Q(t − δ) − σ²/2·Q̈ with δ the rounding
  // (delay_ticks − mean) in seconds: Q − δ·Q̇ + (δ²/2 − σ²/2)·Q̈, and with Q = P + lag·Ṗ +
  // inertia·P̈ (third derivatives dropped) the terms below.
  const double delta = (static_cast<double>(s.delay_ticks) - mean) * pen.tick_s;
  s.lag_s = pen.ff_lag_s - delta;
  s.inertia_s2 = pen.ff_inertia_s2 - delta * pen.ff_lag_s + 0.5 * delta * delta - 0.5 * variance;
  return s;
}

}  // namespace mark
