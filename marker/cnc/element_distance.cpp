#include "marker/cnc/element_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "fonts/overloaded.hpp"

namespace mark {
namespace {

// Does angle a lie on the sweep from start by sweep (radians, either sign)?
bool on_sweep(double a, double start, double sweep) {
  const double two_pi = 2 * std::numbers::pi;
  const double from = sweep >= 0 ? start : start + sweep;
  double d = std::fmod(a - from, two_pi);
  if (d < 0) d += two_pi;
  return d <= std::abs(sweep) + 1e-12;
}

double distance_to_ellipse(const Point& p, const Element& e) {
  // Coarse samples, then a golden-section search around every local minimum (a full ellipse has
  // its nearest point near the seam at t = 0 and t = 1 alike, so one minimum is not enough).
  constexpr int kSamples = 64;
  auto d2 = [&](double t) { return (e.point_at(t) - p).squaredNorm(); };
  std::array<double, kSamples + 1> d{};
  for (int k = 0; k <= kSamples; ++k) d[k] = d2(static_cast<double>(k) / kSamples);
  double best = std::numeric_limits<double>::infinity();
  const double phi = (std::sqrt(5.0) - 1) / 2;
  for (int k = 0; k <= kSamples; ++k) {
    if ((k > 0 && d[k] > d[k - 1]) || (k < kSamples && d[k] > d[k + 1])) continue;
    double a = static_cast<double>(std::max(k - 1, 0)) / kSamples;
    double b = static_cast<double>(std::min(k + 1, kSamples)) / kSamples;
    double x1 = b - phi * (b - a), x2 = a + phi * (b - a), f1 = d2(x1), f2 = d2(x2);
    for (int it = 0; it < 60 && b - a > 1e-15; ++it) {
      if (f1 < f2) {
        b = x2, x2 = x1, f2 = f1, x1 = b - phi * (b - a), f1 = d2(x1);
      } else {
        a = x1, x1 = x2, f1 = f2, x2 = a + phi * (b - a), f2 = d2(x2);
      }
    }
    best = std::min({best, d[k], f1, f2});
  }
  return std::sqrt(best);
}

}  // namespace

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (a + t * ab - p).norm();
}

double distance_to_arc(const Point& p, const CircularArc& arc) {
  const Point d = p - arc.center;
  if (d.squaredNorm() > 0 && on_sweep(std::atan2(d.y(), d.x()), arc.start_angle, arc.sweep))
    return std::abs(d.norm() - arc.radius);
  const Point s = arc.center + arc.radius * Point(std::cos(arc.start_angle), std::sin(arc.start_angle));
  const double ea = arc.start_angle + arc.sweep;
  const Point e = arc.center + arc.radius * Point(std::cos(ea), std::sin(ea));
  return std::min((p - s).norm(), (p - e).norm());
}

double distance_to_element(const Point& p, const Element& element) {
  return std::visit(
      Overloaded{[&](const Line& l) { return distance_to_segment(p, l.start, l.end); },
                 [&](const CircularArc& a) { return distance_to_arc(p, a); },
                 [&](const EllipticalArc&) { return distance_to_ellipse(p, element); }},
      element.geometry());
}

}  // namespace mark
