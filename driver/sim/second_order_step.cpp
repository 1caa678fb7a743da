#include "driver/sim/second_order_step.hpp"

#include <cmath>

namespace mark {

// A 2×2 matrix with eigenvalues s ± q (s = −ζωn, q² = ωn²(ζ² − 1)) has
//   e^{A·t} = c(t)·I + g(t)·(A − s·I),  c = e^{st}·cosh(qt),  g = e^{st}·sinh(qt)/q,
// with cos/sin for q² < 0. Overdamped loops use the two real exponentials e^{(s±q)t} directly
// (e^{st}·cosh(qt) would overflow for a large ζ); near critical damping sinh(qt)/q is its series.
SecondOrderStep second_order_step(double wn, double zeta, double dt) {
  const double s = -zeta * wn;
  const double q2 = wn * wn * (zeta * zeta - 1);
  const double qt2 = q2 * dt * dt;
  double c = 0, g = 0;
  if (std::abs(qt2) < 1e-8) {  // critical: cosh ≈ 1 + (qt)²/2, sinh(qt)/q ≈ t·(1 + (qt)²/6)
    const double e = std::exp(s * dt);
    c = e * (1 + qt2 / 2);
    g = e * dt * (1 + qt2 / 6);
  } else if (q2 > 0) {  // overdamped
    const double q = std::sqrt(q2);
    const double fast = std::exp((s - q) * dt), slow = std::exp((s + q) * dt);
    c = (slow + fast) / 2;
    g = (slow - fast) / (2 * q);
  } else {  // underdamped
    const double w = std::sqrt(-q2);
    const double e = std::exp(s * dt);
    c = e * std::cos(w * dt);
    g = e * std::sin(w * dt) / w;
  }
  // A − s·I = [[−s, 1], [−ωn², −2ζωn − s]] = [[ζωn, 1], [−ωn², −ζωn]].
  SecondOrderStep m;
  m.yy = c + g * zeta * wn;
  m.yv = g;
  m.vy = -g * wn * wn;
  m.vv = c - g * zeta * wn;
  m.lag = 2 * zeta / wn;
  m.dt = dt;
  return m;
}

}  // namespace mark
