#include "driver/sim/stylus_head_model.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace mark {

double StylusHeadModel::static_gain() const {
  double g = 0;
  for (const StylusMode& m : modes) g += m.gain;
  return g;
}

StylusHeadModel default_stylus_head() {
  return {{{1800, 0.06, 0.8}, {5500, 0.04, 0.2}}};
}

void validate(const StylusHeadModel& head) {
  if (head.modes.empty()) throw std::invalid_argument("stylus head: at least one resonance is needed");
  for (std::size_t i = 0; i < head.modes.size(); ++i) {
    const StylusMode& m = head.modes[i];
    char msg[200];
    if (!(m.freq_hz > 0 && m.freq_hz < kStylusRate_hz / 4)) {
      std::snprintf(msg, sizeof msg, "stylus head: resonance %zu at %g Hz is outside 0 .. %g Hz", i + 1,
                    m.freq_hz, kStylusRate_hz / 4);
      throw std::invalid_argument(msg);
    }
    if (!(m.damping > 0 && m.damping < 1)) {
      std::snprintf(msg, sizeof msg, "stylus head: resonance %zu has damping %g, outside 0 .. 1", i + 1,
                    m.damping);
      throw std::invalid_argument(msg);
    }
    if (!(m.gain > 0 && std::isfinite(m.gain))) {
      std::snprintf(msg, sizeof msg, "stylus head: resonance %zu has gain %g, must be positive", i + 1, m.gain);
      throw std::invalid_argument(msg);
    }
  }
}

ModeStep discretise(const StylusMode& mode, double tick_s) {
  // Exact transition matrix of x'' + 2ζω x' + ω² x = 0 over one tick (underdamped).
  const double w = 2 * std::numbers::pi * mode.freq_hz;
  const double sigma = mode.damping * w;
  const double wd = w * std::sqrt(1 - mode.damping * mode.damping);
  const double e = std::exp(-sigma * tick_s);
  const double c = std::cos(wd * tick_s), s = std::sin(wd * tick_s);
  return {{e * (c + sigma / wd * s), e * s / wd, -e * w * w / wd * s, e * (c - sigma / wd * s)},
          mode.gain};
}

namespace {

// The sampled state after each tick over the held drive, (position, velocity), at f.
std::pair<std::complex<double>, std::complex<double>> held_state(const StylusHeadModel& head, double freq_hz,
                                                                 double tick_s) {
  using C = std::complex<double>;
  const C zinv = std::polar(1.0, -2 * std::numbers::pi * freq_hz * tick_s);
  C x = 0, v = 0;
  for (const StylusMode& m : head.modes) {
    const ModeStep st = discretise(m, tick_s);
    const auto& p = st.phi;
    // b = (I − Φ)(1, 0)ᵀ;  solve (I − Φ z⁻¹) s = b by Cramer's rule.
    const C b0 = 1 - p[0], b1 = -p[2];
    const C a00 = 1.0 - p[0] * zinv, a01 = -p[1] * zinv, a10 = -p[2] * zinv, a11 = 1.0 - p[3] * zinv;
    const C det = a00 * a11 - a01 * a10;
    x += st.gain * (b0 * a11 - a01 * b1) / det;
    v += st.gain * (a00 * b1 - a10 * b0) / det;
  }
  return {x, v};
}

}  // namespace

std::complex<double> held_response(const StylusHeadModel& head, double freq_hz, double tick_s) {
  return held_state(head, freq_hz, tick_s).first;
}

std::complex<double> held_velocity_response(const StylusHeadModel& head, double freq_hz, double tick_s) {
  return held_state(head, freq_hz, tick_s).second;
}

std::string describe(const StylusHeadModel& head) {
  std::string out;
  for (const StylusMode& m : head.modes) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s%.0f Hz ζ %.3f g %.2f", out.empty() ? "" : ", ", m.freq_hz,
                  m.damping, m.gain);
    out += buf;
  }
  return out;
}

}  // namespace mark
