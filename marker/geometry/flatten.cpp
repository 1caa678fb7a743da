#include "marker/geometry/flatten.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mark {
namespace {

// A piece count from a real number of pieces: at least 1, at most kMaxPieces, NaN → 1.
std::size_t bounded(double pieces) {
  if (!(pieces > 1)) return 1;
  if (pieces >= double(kMaxPieces)) return kMaxPieces;
  return static_cast<std::size_t>(std::ceil(pieces));
}

}  // namespace

std::size_t chord_count(const Element& e, double tol) {
  if (!(tol > kFinestChordTolMm)) tol = kFinestChordTolMm;  // NaN too
  return std::visit(
      Overloaded{[](const Line&) -> std::size_t { return 1; },
                 [&](const CircularArc& a) {
                   // Chord over angle φ deviates r(1 − cos φ/2) from the arc.
                   const double c = 1 - tol / std::max(a.radius, tol);
                   const double step = c <= -1 ? std::acos(-1.0) : 2 * std::acos(c);
                   return bounded(std::abs(a.sweep) / step);
                 },
                 [&](const EllipticalArc& el) {
                   // |P''(θ)| ≤ max(rx, ry), and a chord over parameter step h deviates at most
                   // |P''|·h²/8 from the curve.
                   const double h = std::sqrt(8 * tol / std::max({el.rx, el.ry, tol}));
                   return bounded(std::abs(el.sweep) / h);
                 }},
      e.geometry());
}

std::size_t spaced_count(const Element& e, double step_mm) {
  const double reach = std::visit(
      Overloaded{[](const Line& l) { return (l.end - l.start).norm(); },
                 [](const CircularArc& a) { return a.radius * std::abs(a.sweep); },
                 [](const EllipticalArc& a) { return std::max(a.rx, a.ry) * std::abs(a.sweep); }},
      e.geometry());
  return bounded(reach / step_mm);
}

std::vector<Point> pieces_of(const Element& e, std::size_t n) {
  std::vector<Point> pts;
  pts.reserve(n + 1);
  pts.push_back(e.start());
  for_each_piece_end(e, n, [&](double x, double y) { pts.emplace_back(x, y); });
  return pts;
}

std::vector<Point> flatten_element(const Element& e, double tol) { return pieces_of(e, chord_count(e, tol)); }

std::vector<Point> chord_element(const Element& e, double step_rad) {
  const double sweep = std::visit(Overloaded{[](const Line&) { return 0.0; },
                                             [](const CircularArc& a) { return a.sweep; },
                                             [](const EllipticalArc& el) { return el.sweep; }},
                                  e.geometry());
  return pieces_of(e, bounded(std::abs(sweep) / step_rad - 1e-9));
}

}  // namespace mark
