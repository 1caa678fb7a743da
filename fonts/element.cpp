// Construction and exact evaluation of elements: points, tangents, bounds, reversal.
#include "fonts/element.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "fonts/overloaded.hpp"

namespace mark {
namespace {

// Unit vector of the ellipse frame: R(rotation)·(rx cos θ, ry sin θ) without the centre.
Point ellipse_offset(const EllipticalArc& e, double theta) {
  const double c = std::cos(e.rotation), s = std::sin(e.rotation);
  const double x = e.rx * std::cos(theta), y = e.ry * std::sin(theta);
  return {c * x - s * y, s * x + c * y};
}

Point ellipse_derivative(const EllipticalArc& e, double theta) {
  const double c = std::cos(e.rotation), s = std::sin(e.rotation);
  const double x = -e.rx * std::sin(theta), y = e.ry * std::cos(theta);
  return {c * x - s * y, s * x + c * y};
}

}  // namespace

bool angle_on_sweep(double a, double start, double sweep) {
  const double from = sweep >= 0 ? start : start + sweep;
  double d = std::fmod(a - from, 2 * kPi);
  if (d < 0) d += 2 * kPi;
  return d <= std::abs(sweep);
}

Element Element::line(const Point& a, const Point& b, bool laser) { return {Line{a, b}, laser}; }

Element Element::arc(const Point& center, double radius, double start_angle, double sweep,
                     bool laser) {
  return {CircularArc{center, radius, start_angle, sweep}, laser};
}

Element Element::arc_through(const Point& start, const Point& end, double radius, bool ccw,
                             bool major, bool laser) {
  const Point chord = end - start;
  const double half = chord.norm() / 2;
  if (!(radius > 0) || half == 0) throw InputError("arc with radius " + std::to_string(radius) +
                                                   " and chord " + std::to_string(2 * half) +
                                                   " has no centre");
  if (half > radius * (1 + 1e-9))
    throw InputError("arc radius " + std::to_string(radius) + " is shorter than half its chord " +
                     std::to_string(half));
  const double h = std::sqrt(std::max(0.0, radius * radius - half * half));
  const Point mid = (start + end) / 2;
  const Point left = Point(-chord.y(), chord.x()) / chord.norm();
  // A counter-clockwise minor arc has its centre to the left of the chord.
  const bool centre_left = ccw != major;
  const Point center = mid + (centre_left ? h : -h) * left;
  const double a0 = std::atan2(start.y() - center.y(), start.x() - center.x());
  const double a1 = std::atan2(end.y() - center.y(), end.x() - center.x());
  double sweep = a1 - a0;
  if (ccw) {
    while (sweep <= 0) sweep += 2 * kPi;
  } else {
    while (sweep >= 0) sweep -= 2 * kPi;
  }
  return arc(center, radius, a0, sweep, laser);
}

Element Element::bulge(const Point& start, const Point& end, double bulge, bool laser) {
  const double chord = (end - start).norm();
  if (bulge == 0 || chord == 0) return line(start, end, laser);
  const double sweep = 4 * std::atan(bulge);
  const double radius = chord / (2 * std::sin(std::abs(sweep) / 2));
  return arc_through(start, end, radius, sweep > 0, std::abs(sweep) > kPi, laser);
}

Element Element::ellipse(const Point& center, double rx, double ry, double rotation,
                         double start_param, double sweep, bool laser) {
  return {EllipticalArc{center, rx, ry, rotation, start_param, sweep}, laser};
}

Point Element::point_at(double t) const {
  return std::visit(
      Overloaded{
          [&](const Line& l) -> Point { return l.start + t * (l.end - l.start); },
          [&](const CircularArc& a) -> Point {
            const double th = a.start_angle + t * a.sweep;
            return a.center + a.radius * Point(std::cos(th), std::sin(th));
          },
          [&](const EllipticalArc& e) -> Point {
            return e.center + ellipse_offset(e, e.start_param + t * e.sweep);
          }},
      geometry_);
}

Point Element::tangent_at(double t) const {
  const Point d = std::visit(
      Overloaded{[&](const Line& l) -> Point { return l.end - l.start; },
                 [&](const CircularArc& a) -> Point {
                   const double th = a.start_angle + t * a.sweep;
                   return a.sweep * Point(-std::sin(th), std::cos(th));
                 },
                 [&](const EllipticalArc& e) -> Point {
                   return e.sweep * ellipse_derivative(e, e.start_param + t * e.sweep);
                 }},
      geometry_);
  const double n = d.norm();
  return n > 0 ? Point(d / n) : Point(0, 0);
}

double Element::length() const { return length_between(0.0, 1.0); }

double Element::length_between(double t0, double t1) const {
  return std::visit(
      Overloaded{[&](const Line& l) { return (t1 - t0) * (l.end - l.start).norm(); },
                 [&](const CircularArc& a) { return (t1 - t0) * a.radius * std::abs(a.sweep); },
                 [&](const EllipticalArc& e) {
                   const double th0 = e.start_param + t0 * e.sweep;
                   const double th1 = e.start_param + t1 * e.sweep;
                   return ellipse_arc_length(e.rx, e.ry, std::min(th0, th1), std::max(th0, th1));
                 }},
      geometry_);
}

Box Element::bounds() const {
  Box box;
  box.add(start());
  box.add(end());
  std::visit(Overloaded{[](const Line&) {},
                        [&](const CircularArc& a) {
                          for (int k = 0; k < 4; ++k) {
                            const double th = k * kPi / 2;
                            if (angle_on_sweep(th, a.start_angle, a.sweep))
                              box.add(a.center + a.radius * Point(std::cos(th), std::sin(th)));
                          }
                        },
                        [&](const EllipticalArc& e) {
                          // Parameters where dx/dθ = 0 and dy/dθ = 0, and their opposites.
                          const double c = std::cos(e.rotation), s = std::sin(e.rotation);
                          const double tx = std::atan2(-e.ry * s, e.rx * c);
                          const double ty = std::atan2(e.ry * c, e.rx * s);
                          for (double th : {tx, tx + kPi, ty, ty + kPi})
                            if (angle_on_sweep(th, e.start_param, e.sweep))
                              box.add(e.center + ellipse_offset(e, th));
                        }},
             geometry_);
  return box;
}

Element Element::reversed() const {
  return std::visit(
      Overloaded{[&](const Line& l) { return line(l.end, l.start, laser_); },
                 [&](const CircularArc& a) {
                   return arc(a.center, a.radius, a.start_angle + a.sweep, -a.sweep, laser_);
                 },
                 [&](const EllipticalArc& e) {
                   return ellipse(e.center, e.rx, e.ry, e.rotation, e.start_param + e.sweep,
                                  -e.sweep, laser_);
                 }},
      geometry_);
}

}  // namespace mark
