#include "marker/cnc/flatten.hpp"

#include <algorithm>
#include <cmath>

#include "fonts/overloaded.hpp"

namespace mark {
namespace {

constexpr int kMaxPieces = 1 << 16;  // bound for degenerate tolerances

std::vector<Point> uniform(const Element& e, int pieces) {
  pieces = std::clamp(pieces, 1, kMaxPieces);
  std::vector<Point> pts;
  pts.reserve(static_cast<std::size_t>(pieces) + 1);
  for (int k = 0; k <= pieces; ++k) pts.push_back(e.point_at(static_cast<double>(k) / pieces));
  return pts;
}

}  // namespace

std::vector<Point> flatten_element(const Element& e, double tol) {
  tol = std::max(tol, 1e-9);
  return std::visit(
      Overloaded{[&](const Line& l) { return std::vector<Point>{l.start, l.end}; },
                 [&](const CircularArc& a) {
                   // Chord over angle φ deviates r(1 − cos φ/2) from the arc.
                   const double c = 1 - tol / std::max(a.radius, tol);
                   const double step = c <= -1 ? std::acos(-1.0) : 2 * std::acos(c);
                   return uniform(e, static_cast<int>(std::ceil(std::abs(a.sweep) / step)));
                 },
                 [&](const EllipticalArc& el) {
                   // |P''(θ)| ≤ max(rx, ry), and a chord over parameter step h deviates at most
                   // |P''|·h²/8 from the curve.
                   const double h = std::sqrt(8 * tol / std::max({el.rx, el.ry, tol}));
                   return uniform(e, static_cast<int>(std::ceil(std::abs(el.sweep) / h)));
                 }},
      e.geometry());
}

std::vector<Point> chord_element(const Element& e, double step_rad) {
  return std::visit(
      Overloaded{[&](const Line& l) { return std::vector<Point>{l.start, l.end}; },
                 [&](const CircularArc& a) {
                   return uniform(e, static_cast<int>(std::ceil(std::abs(a.sweep) / step_rad - 1e-9)));
                 },
                 [&](const EllipticalArc& el) {
                   return uniform(e, static_cast<int>(std::ceil(std::abs(el.sweep) / step_rad - 1e-9)));
                 }},
      e.geometry());
}

}  // namespace mark
