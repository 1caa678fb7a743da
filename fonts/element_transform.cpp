// Affine transforms of elements, exact: a circular arc stays circular under a similarity
// (rotation, uniform scale, reflection) and becomes an exact elliptical arc otherwise; an
// elliptical arc that a transform makes round becomes a circular arc again.
#include <Eigen/SVD>
#include <cmath>
#include <optional>

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

// A linear map that is a similarity: scale·R(angle), or scale·Refl(angle) when `reflect`, with
// Refl(α) = R(α)·diag(1, −1).
struct Similarity {
  double scale;
  double angle;
  bool reflect;
};

std::optional<Similarity> as_similarity(const Eigen::Matrix2d& m) {
  const double a = m(0, 0), b = m(1, 0), c = m(0, 1), d = m(1, 1);
  const double scale = std::hypot(a, b);
  const double tol = kRoundTol * scale;
  if (scale == 0) return std::nullopt;
  if (std::abs(c + b) <= tol && std::abs(d - a) <= tol) return Similarity{scale, std::atan2(b, a), false};
  if (std::abs(c - b) <= tol && std::abs(d + a) <= tol) return Similarity{scale, std::atan2(b, a), true};
  return std::nullopt;
}

}  // namespace

Element Element::transformed(const Affine& transform) const {
  const Eigen::Matrix2d m = transform.linear();
  // Layout places every glyph with a rotation and translation: keep that path free of the SVD.
  if (const auto sim = as_similarity(m); sim && kind() != ElementKind::line) {
    if (const auto* a = std::get_if<CircularArc>(&geometry_)) {
      return sim->reflect ? arc(transform * a->center, sim->scale * a->radius,
                                sim->angle - a->start_angle, -a->sweep, laser_)
                          : arc(transform * a->center, sim->scale * a->radius,
                                a->start_angle + sim->angle, a->sweep, laser_);
    }
    const auto& e = std::get<EllipticalArc>(geometry_);
    // Refl(α)·R(β) = Refl(α − β) and Refl(γ)·diag(rx, ry)·(cos θ, sin θ) = R(γ)·diag(rx, ry)·(cos −θ, sin −θ).
    return sim->reflect ? ellipse(transform * e.center, sim->scale * e.rx, sim->scale * e.ry,
                                  sim->angle - e.rotation, -e.start_param, -e.sweep, laser_)
                        : ellipse(transform * e.center, sim->scale * e.rx, sim->scale * e.ry,
                                  e.rotation + sim->angle, e.start_param, e.sweep, laser_);
  }
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
