#include "marker/locus/ellipse_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mark {
namespace {

constexpr double kPi = std::numbers::pi;
// Nodes per full turn of the tangent. The quintic interpolant's error falls as the sixth power
// of the spacing; at 96 per turn consecutive samples stay uniform to < 1e-6 relative up to axis
// ratios of 10 (tests/marker/locus_test.cpp).
constexpr double kNodesPerTurn = 96;
constexpr int kNewtonSteps = 3;

// Tangent direction angle minus θ, smooth and bounded: ψ(θ) = θ + π/2 + bend(θ).
double bend(double rx, double ry, double th) {
  const double s = std::sin(th), c = std::cos(th);
  return std::atan((rx - ry) * s * c / (rx * s * s + ry * c * c));
}

}  // namespace

void EllipseTable::build(const Element& ellipse) {
  const auto& e = std::get<EllipticalArc>(ellipse.geometry());
  cx_ = e.center.x(), cy_ = e.center.y(), rx_ = e.rx, ry_ = e.ry;
  rc_ = std::cos(e.rotation), rs_ = std::sin(e.rotation);
  sign_ = e.sweep >= 0 ? 1.0 : -1.0;
  th0_ = e.start_param;
  const double th0 = th0_, th1 = e.start_param + e.sweep;

  // Node parameters at equal steps of the unwrapped tangent angle u(θ) = θ + bend(θ); the
  // inverse is closed-form: the tangent (−rx sin θ, ry cos θ) points along ψ = u + π/2.
  const double u0 = th0 + bend(rx_, ry_, th0), u1 = th1 + bend(rx_, ry_, th1);
  const std::size_t segments = std::max<std::size_t>(
      2, static_cast<std::size_t>(std::ceil(std::abs(u1 - u0) / (2 * kPi) * kNodesPerTurn)));
  phi_.assign(segments + 1, 0.0);
  s_.assign(segments + 1, 0.0);
  d1_.assign(segments + 1, 0.0);
  d2_.assign(segments + 1, 0.0);
  double prev = th0;
  for (std::size_t j = 1; j <= segments; ++j) {
    double th = th1;
    if (j < segments) {
      const double u = u0 + (u1 - u0) * static_cast<double>(j) / segments;
      const double psi = u + kPi / 2;
      th = std::atan2(-std::cos(psi) / rx_, std::sin(psi) / ry_);
      const double near = u - bend(rx_, ry_, prev);  // θ = u − bend(θ): unwrap next to it
      th += 2 * kPi * std::round((near - th) / (2 * kPi));
    }
    phi_[j] = sign_ * (th - th0);
    const double t_prev = (prev - th0) / e.sweep, t = (th - th0) / e.sweep;
    s_[j] = s_[j - 1] + ellipse.length_between(t_prev, t);
    prev = th;
  }
  for (std::size_t j = 0; j <= segments; ++j) {
    const double th = th0 + sign_ * phi_[j];
    const double sn = std::sin(th), cs = std::cos(th);
    const double g = std::hypot(rx_ * sn, ry_ * cs);
    d1_[j] = g;
    d2_[j] = sign_ * (rx_ * rx_ - ry_ * ry_) * sn * cs / g;
  }
}

double EllipseTable::theta_at(double s, Cursor& cur) const {
  const std::size_t last = s_.size() - 2;  // index of the last interval
  std::size_t j = cur.node;
  if (s < s_[j]) j = 0, cur.x = 0;  // lookups went backwards: restart
  bool moved = false;
  while (j < last && s > s_[j + 1]) ++j, moved = true;
  const double h = phi_[j + 1] - phi_[j];
  const double s0 = s_[j], s1 = s_[j + 1];
  const double a1 = h * d1_[j], a2 = h * h * d2_[j];
  const double b1 = h * d1_[j + 1], b2 = h * h * d2_[j + 1];
  // Start from the previous sample's position, or linearly inside a new interval.
  double x = moved || cur.node != j ? (s - s0) / (s1 - s0) : cur.x;
  for (int it = 0; it < kNewtonSteps; ++it) {
    const double x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x;
    const double f = (1 - 10 * x3 + 15 * x4 - 6 * x5) * s0 + (x - 6 * x3 + 8 * x4 - 3 * x5) * a1 +
                     (0.5 * x2 - 1.5 * x3 + 1.5 * x4 - 0.5 * x5) * a2 +
                     (10 * x3 - 15 * x4 + 6 * x5) * s1 + (-4 * x3 + 7 * x4 - 3 * x5) * b1 +
                     (0.5 * x3 - x4 + 0.5 * x5) * b2;
    const double df = (-30 * x2 + 60 * x3 - 30 * x4) * s0 +
                      (1 - 18 * x2 + 32 * x3 - 15 * x4) * a1 +
                      (x - 4.5 * x2 + 6 * x3 - 2.5 * x4) * a2 + (30 * x2 - 60 * x3 + 30 * x4) * s1 +
                      (-12 * x2 + 28 * x3 - 15 * x4) * b1 + (1.5 * x2 - 4 * x3 + 2.5 * x4) * b2;
    x = std::clamp(x - (f - s) / df, 0.0, 1.0);
  }
  cur.node = j;
  cur.x = x;
  return th0_ + sign_ * (phi_[j] + x * h);
}

}  // namespace mark
