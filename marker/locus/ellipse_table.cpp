#include "marker/locus/ellipse_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/numbers.hpp"

namespace mark {
namespace {

// Node spacing: a turn of the tangent is split into this many steps, more for flatter ellipses
// (whose curvature also changes faster), and no step spans more than kMaxStep of the parameter
// (so 5-point Gauss–Legendre stays exact on it). The interpolant's error falls with the fifth
// power of the spacing in the sample spacing; these counts keep consecutive samples uniform to
// < 1e-6 relative (measured ≤ 6.4e-7) up to an axis ratio of 10 (tests/marker/locus_test.cpp).
constexpr double kStepsPerTurn = 48, kStepsPerTurnPerRatio = 32;
constexpr double kMaxStep = 0.2;

// Arc length between two close parameters, where |P'| is smooth: 5-point Gauss–Legendre.
double short_arc_length(double rx, double ry, double a, double b) {
  static constexpr double kX[3] = {0.0, 0.5384693101056831, 0.9061798459386640};
  static constexpr double kW[3] = {0.5688888888888889, 0.4786286704993665, 0.2369268850561891};
  const double m = (a + b) / 2, h = (b - a) / 2;
  auto g = [&](double t) {
    const double sn = std::sin(t), c = std::cos(t);
    return std::sqrt(rx * rx * sn * sn + ry * ry * c * c);
  };
  double sum = kW[0] * g(m);
  for (int i = 1; i < 3; ++i) sum += kW[i] * (g(m - h * kX[i]) + g(m + h * kX[i]));
  return std::abs(sum * h);
}

}  // namespace

void EllipseTable::build(const Element& ellipse) {
  const auto& e = std::get<EllipticalArc>(ellipse.geometry());
  const double rx = e.rx, ry = e.ry, th0 = e.start_param;
  const double rc = std::cos(e.rotation), rs = std::sin(e.rotation);
  const double sign = e.sweep >= 0 ? 1.0 : -1.0, span = std::abs(e.sweep);
  const double ratio = std::max(rx, ry) / std::max(std::min(rx, ry), 1e-300);
  const double du = 2 * kPi / (kStepsPerTurn + kStepsPerTurnPerRatio * ratio);

  // Node at parameter offset phi (θ = θ0 + sign·phi) and arc length s; returns |P'(θ)|.
  auto add_node = [&](double phi, double s) {
    const double th = th0 + sign * phi, sn = std::sin(th), c = std::cos(th);
    const double g2 = rx * rx * sn * sn + ry * ry * c * c, g = std::sqrt(g2);
    const double gp = (rx * rx - ry * ry) * sn * c / g;  // d|P'|/dθ
    // Ellipse frame: P' = (−rx sin, ry cos), P'' = (−rx cos, −ry sin). In arc length along the
    // direction of travel: dP/ds = sign·P'/g, d²P/ds² = P''/g² − P'·g'/g³.
    const double t[2] = {sign * -rx * sn / g, sign * ry * c / g};
    const double k[2] = {-rx * c / g2 + rx * sn * gp / (g2 * g), -ry * sn / g2 - ry * c * gp / (g2 * g)};
    Node n;
    n.s = s;
    n.p[0] = e.center.x() + rc * rx * c - rs * ry * sn;
    n.p[1] = e.center.y() + rs * rx * c + rc * ry * sn;
    n.tan[0] = rc * t[0] - rs * t[1], n.tan[1] = rs * t[0] + rc * t[1];
    n.curv[0] = rc * k[0] - rs * k[1], n.curv[1] = rs * k[0] + rc * k[1];
    nodes_.push_back(n);
    return g;
  };

  nodes_.clear();
  double phi = 0, g = add_node(0, 0);
  while (phi < span) {
    // The tangent turns at dψ/dθ = rx·ry/|P'|²: a tangent step du is this much parameter.
    double step = std::min(kMaxStep, du * g * g / (rx * ry));
    if (phi + 1.5 * step > span) step = span - phi;  // the last interval, not a sliver
    const double a = th0 + sign * phi, b = th0 + sign * (phi + step);
    phi += step;
    g = add_node(phi, nodes_.back().s + short_arc_length(rx, ry, a, b));
  }
  // The summed pieces agree with the whole arc's adaptive length to ~1e-15; pin the end to it.
  const double scale = ellipse.length_between(0.0, 1.0) / nodes_.back().s;
  for (Node& n : nodes_) n.s *= scale;
  for (std::size_t j = 0; j + 1 < nodes_.size(); ++j) {
    Node& a = nodes_[j];
    const Node& b = nodes_[j + 1];
    const double len = b.s - a.s, len2 = len * len;
    a.inv_len = 1.0 / len;
    // The Hermite basis (h0 = 1 − h5, h5 = 10t³ − 15t⁴ + 6t⁵, h1, h4 on the tangents scaled by
    // len, h2, h3 on the curvatures scaled by len²) gathered by powers of t.
    for (int k = 0; k < 2; ++k) {
      const double dp = b.p[k] - a.p[k], ta = len * a.tan[k], tb = len * b.tan[k];
      const double ka = len2 * a.curv[k], kb = len2 * b.curv[k];
      a.c[k][0] = a.p[k];
      a.c[k][1] = ta;
      a.c[k][2] = 0.5 * ka;
      a.c[k][3] = 10 * dp - 6 * ta - 4 * tb - 1.5 * ka + 0.5 * kb;
      a.c[k][4] = -15 * dp + 8 * ta + 7 * tb + 1.5 * ka - kb;
      a.c[k][5] = 6 * dp - 3 * ta - 3 * tb - 0.5 * ka + 0.5 * kb;
    }
  }
}

}  // namespace mark
