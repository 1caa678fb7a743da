// Affine transforms of elements, exact: a circular arc stays circular under a similarity
// (rotation, uniform scale, reflection) and becomes an exact elliptical arc otherwise; an
// elliptical arc that a transform makes round becomes a circular arc again.
#include <Eigen/SVD>
#include <cmath>

#include "fonts/element.hpp"
#include "fonts/overloaded.hpp"

namespace mark {
namespace {

constexpr double kRoundTol = 1e-12;  // relative difference of the axes that still counts as a circle

// The linear part M of an ellipse point c + M·(cos θ, sin θ), written back as an elliptical arc
// (or a circular one when M is a similarity). M = U·Σ·Vᵀ; with U made a rotation, Vᵀ is either a
// rotation by −ψ (θ' = θ − ψ) or a reflection [[cos α, sin α], [sin α, −cos α]] (θ' = α − θ, the
// sweep changes sign).
Element from_linear_part(const Point& center, const Eigen::Matrix2d& m, double start, double sweep,
                         bool laser) {
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix2d u = svd.matrixU();
  Eigen::Matrix2d v = svd.matrixV();
  const Eigen::Vector2d sigma = svd.singularValues();
  if (u.determinant() < 0) {
    u.col(1) *= -1;
    v.col(1) *= -1;
  }
  const Eigen::Matrix2d vt = v.transpose();
  double start2, sweep2;
  if (vt.determinant() > 0) {
    const double psi = std::atan2(v(1, 0), v(0, 0));
    start2 = start - psi;
    sweep2 = sweep;
  } else {
    const double alpha = std::atan2(vt(0, 1), vt(0, 0));
    start2 = alpha - start;
    sweep2 = -sweep;
  }
  const double rotation = std::atan2(u(1, 0), u(0, 0));
  if (std::abs(sigma(0) - sigma(1)) <= kRoundTol * sigma(0))
    return Element::arc(center, (sigma(0) + sigma(1)) / 2, start2 + rotation, sweep2, laser);
  return Element::ellipse(center, sigma(0), sigma(1), rotation, start2, sweep2, laser);
}

Eigen::Matrix2d rotation_matrix(double a) {
  Eigen::Matrix2d r;
  r << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return r;
}

}  // namespace

Element Element::transformed(const Affine& transform) const {
  const Eigen::Matrix2d m = transform.linear();
  return std::visit(
      Overloaded{
          [&](const Line& l) { return line(transform * l.start, transform * l.end, laser_); },
          [&](const CircularArc& a) {
            return from_linear_part(transform * a.center, m * a.radius, a.start_angle, a.sweep,
                                    laser_);
          },
          [&](const EllipticalArc& e) {
            Eigen::Matrix2d axes = rotation_matrix(e.rotation) *
                                   Eigen::DiagonalMatrix<double, 2>(e.rx, e.ry);
            return from_linear_part(transform * e.center, m * axes, e.start_param, e.sweep,
                                    laser_);
          }},
      geometry_);
}

}  // namespace mark
