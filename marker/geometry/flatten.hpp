#pragma once
// Curves to straight pieces, in one place for every stage that must flatten an exact element:
// a board without arcs (chords within its chord tolerance), Clipper's polygons (fill, CNC
// pockets), the red-pointer frame, the quality figures' intended strokes (points a given
// distance apart), and F-Engrave's fixed-angle chords for comparison. Elements stay exact
// everywhere else; nothing is pre-flattened for convenience.
//
// Pieces are of equal parameter step, so piece k ends at point_at(k/n) (to within the
// recurrence's rounding, about k·1e-16 of the radius) and the last ends exactly at the element's
// end.
#include <cmath>
#include <cstddef>
#include <vector>

#include "fonts/element.hpp"
#include "fonts/overloaded.hpp"

namespace mark {

// The most pieces one element is split into, whatever the tolerance: an absurd tolerance (or a
// huge radius) costs at most this many points (16 MB), never an unbounded allocation. No
// tolerance in its documented range comes near it.
inline constexpr std::size_t kMaxPieces = std::size_t{1} << 20;
// Tolerances finer than this (or not a number) are taken as this, far below any device's
// resolution.
inline constexpr double kFinestChordTolMm = 1e-9;

// Pieces whose chords leave the exact curve by at most tol_mm: a circular arc's chord over φ
// deviates r(1 − cos φ/2), an ellipse arc's over parameter step h at most max(rx, ry)·h²/8.
// A line is one piece.
std::size_t chord_count(const Element& element, double tol_mm);

// Pieces such that consecutive points are at most step_mm apart (the parameter speed of an arc
// never exceeds its larger radius × |sweep|). A line of length ≤ step_mm is one piece.
std::size_t spaced_count(const Element& element, double step_mm);

// Calls emit(x, y) for the points at parameters k/n, k = 1 … n (the start point is the caller's):
// the angle advances by a fixed rotation rather than a sin/cos per point, and the last point is
// the element's exact end, evaluated as Element::point_at evaluates it. Each curve costs three
// sincos (start, step, end), an ellipse one more (its rotation). Points are built coordinate by
// coordinate: as Eigen expressions, c and s were stored as two doubles and read back as one
// 16-byte vector, a failed store-to-load forward on every point (a quarter of the LMC
// conversion's time).
template <class F>
void for_each_piece_end(const Element& e, std::size_t n, F&& emit) {
  const auto rotate = [&](double c, double s, double step, auto&& place) {
    const double dc = std::cos(step), ds = std::sin(step);
    for (std::size_t k = 1; k < n; ++k) {
      const double c1 = c * dc - s * ds;
      s = s * dc + c * ds;
      c = c1;
      place(c, s);
    }
  };
  std::visit(Overloaded{[&](const Line& l) {
                          const Point d = l.end - l.start;
                          for (std::size_t k = 1; k < n; ++k) {
                            const double t = static_cast<double>(k) / static_cast<double>(n);
                            emit(l.start.x() + t * d.x(), l.start.y() + t * d.y());
                          }
                          const Point p = l.start + 1.0 * d;  // point_at(1)
                          emit(p.x(), p.y());
                        },
                        [&](const CircularArc& a) {
                          const auto on_circle = [&](double c, double s) {
                            emit(a.center.x() + a.radius * c, a.center.y() + a.radius * s);
                          };
                          // The start direction from the start point, as the element has it.
                          const double c0 = std::cos(a.start_angle), s0 = std::sin(a.start_angle);
                          const double sx = a.center.x() + a.radius * c0;
                          const double sy = a.center.y() + a.radius * s0;
                          rotate((sx - a.center.x()) / a.radius, (sy - a.center.y()) / a.radius,
                                 a.sweep / double(n), on_circle);
                          const double th = a.start_angle + 1.0 * a.sweep;
                          on_circle(std::cos(th), std::sin(th));
                        },
                        [&](const EllipticalArc& el) {
                          const double rc = std::cos(el.rotation), rs = std::sin(el.rotation);
                          const auto on_ellipse = [&](double c, double s) {
                            const double x = el.rx * c, y = el.ry * s;
                            emit(el.center.x() + (rc * x - rs * y), el.center.y() + (rs * x + rc * y));
                          };
                          rotate(std::cos(el.start_param), std::sin(el.start_param),
                                 el.sweep / double(n), on_ellipse);
                          const double th = el.start_param + 1.0 * el.sweep;
                          on_ellipse(std::cos(th), std::sin(th));
                        }},
             e.geometry());
}

// The element as n pieces: its start, then every piece's end.
std::vector<Point> pieces_of(const Element& element, std::size_t n);

// Start and end included, chords within chord_tol_mm (chord_count).
std::vector<Point> flatten_element(const Element& element, double chord_tol_mm);

// F-Engrave's approach: arcs (circular and elliptical) split into chords of at most `step_rad`
// of their angle parameter (F-Engrave: 5°). Lines stay single segments.
std::vector<Point> chord_element(const Element& element, double step_rad);

}  // namespace mark
