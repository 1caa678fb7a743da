#include "marker/cnc/arc_spline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/numbers.hpp"
#include "fonts/overloaded.hpp"
#include "marker/cnc/element_distance.hpp"
#include "marker/geometry/flatten.hpp"

namespace mark {
namespace {

constexpr int kMaxDepth = 24;
// Share of the tolerance the geometry may use; the rest is kept for rounding coordinates to the
// output precision.
constexpr double kFitShare = 0.9;

Point left_normal(const Point& t) { return {-t.y(), t.x()}; }

void push_circular(const CircularArc& a, const ArcSplineOptions& o, std::vector<Element>& out) {
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(a.sweep) / kPi - 1e-12)));
  const double step = a.sweep / pieces;
  for (int k = 0; k < pieces; ++k) {
    const Element piece = Element::arc(a.center, a.radius, a.start_angle + k * step, step);
    const double chord = 2 * a.radius * std::sin(std::abs(step) / 2);
    const double sagitta = a.radius * (1 - std::cos(step / 2));
    if (chord >= o.min_arc_chord_mm && sagitta >= o.min_arc_sagitta_mm) {
      out.push_back(piece);
      continue;
    }
    // Too small to be an arc for a controller: chords within the tolerance instead.
    const std::vector<Point> pts = flatten_element(piece, o.tolerance_mm * kFitShare);
    for (std::size_t i = 1; i < pts.size(); ++i) out.push_back(Element::line(pts[i - 1], pts[i]));
  }
}

// The arc that leaves `from` along unit tangent `t` and passes through `to`; a line when the
// three are collinear.
Element tangent_arc(const Point& from, const Point& t, const Point& to) {
  const Point v = to - from;
  const double side = left_normal(t).dot(v);
  if (std::abs(side) <= 1e-12 * v.squaredNorm() || v.squaredNorm() == 0)
    return Element::line(from, to);
  const double rho = v.squaredNorm() / (2 * side);  // > 0: centre on the left, counter-clockwise
  const Point c = from + rho * left_normal(t);
  const double a0 = std::atan2(from.y() - c.y(), from.x() - c.x());
  double sweep = std::atan2(to.y() - c.y(), to.x() - c.x()) - a0;
  if (rho > 0 && sweep < 0) sweep += 2 * kPi;
  if (rho < 0 && sweep > 0) sweep -= 2 * kPi;
  return Element::arc(c, std::abs(rho), a0, sweep);
}

// Biarc between p0 (tangent t0) and p1 (tangent t1) with equal tangent lengths d: the join
// point is ((p0 + d·t0) + (p1 − d·t1)) / 2 with |(p1 − d·t1) − (p0 + d·t0)| = 2d.
bool biarc(const Point& p0, const Point& t0, const Point& p1, const Point& t1, Element& a,
           Element& b) {
  const Point v = p1 - p0;
  const Point t = t0 + t1;
  const double qa = t.squaredNorm() - 4, qb = -2 * v.dot(t), qc = v.squaredNorm();
  double d;
  if (std::abs(qa) < 1e-12) {
    if (std::abs(qb) < 1e-15) return false;
    d = -qc / qb;
  } else {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return false;
    d = (-qb - std::sqrt(disc)) / (2 * qa);
  }
  if (!(d > 0) || !std::isfinite(d)) return false;
  const Point join = ((p0 + d * t0) + (p1 - d * t1)) / 2;
  a = tangent_arc(p0, t0, join);
  // The second arc, run backwards from p1 along −t1, then reversed.
  b = tangent_arc(p1, -t1, join).reversed();
  return true;
}

double spline_distance(const Point& p, const Element& a, const Element& b) {
  return std::min(distance_to_element(p, a), distance_to_element(p, b));
}

void fit_ellipse(const Element& piece, double tol, int depth, const ArcSplineOptions& o,
                 std::vector<Element>& out) {
  Element a = piece, b = piece;
  bool ok = biarc(piece.start(), piece.tangent_at(0), piece.end(), piece.tangent_at(1), a, b);
  if (ok) {
    constexpr int kSamples = 24;
    for (int k = 1; k < kSamples && ok; ++k)
      ok = spline_distance(piece.point_at(static_cast<double>(k) / kSamples), a, b) <= tol;
    // And the other way: the arcs' own midpoints must stay near the curve.
    ok = ok && distance_to_element(a.point_at(0.5), piece) <= tol &&
         distance_to_element(b.point_at(0.5), piece) <= tol;
  }
  if (!ok && depth < kMaxDepth) {
    const auto& e = std::get<EllipticalArc>(piece.geometry());
    const double half = e.sweep / 2;
    fit_ellipse(Element::ellipse(e.center, e.rx, e.ry, e.rotation, e.start_param, half), tol,
                depth + 1, o, out);
    fit_ellipse(Element::ellipse(e.center, e.rx, e.ry, e.rotation, e.start_param + half, half),
                tol, depth + 1, o, out);
    return;
  }
  if (!ok) {  // unreachable in practice: the curve is shorter than any tolerance by now
    out.push_back(Element::line(piece.start(), piece.end()));
    return;
  }
  for (const Element& arc : {a, b}) {
    if (const auto* c = std::get_if<CircularArc>(&arc.geometry()))
      push_circular(*c, o, out);
    else
      out.push_back(arc);
  }
}

}  // namespace

std::vector<Element> arc_spline(const Element& element, const ArcSplineOptions& o) {
  std::vector<Element> out;
  std::visit(
      Overloaded{[&](const Line& l) { out.push_back(Element::line(l.start, l.end)); },
                 [&](const CircularArc& a) { push_circular(a, o, out); },
                 [&](const EllipticalArc& e) {
                   if (o.ellipse_chords) {
                     const std::vector<Point> pts = flatten_element(element, o.tolerance_mm * kFitShare);
                     for (std::size_t k = 1; k < pts.size(); ++k)
                       out.push_back(Element::line(pts[k - 1], pts[k]));
                     return;
                   }
                   // Quarter-turn pieces: a biarc cannot follow a turn of more than ~180°.
                   const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(e.sweep) / (kPi / 2) - 1e-12)));
                   const double step = e.sweep / pieces;
                   for (int k = 0; k < pieces; ++k)
                     fit_ellipse(Element::ellipse(e.center, e.rx, e.ry, e.rotation,
                                                  e.start_param + k * step, step),
                                 o.tolerance_mm * kFitShare, 0, o, out);
                 }},
      element.geometry());
  for (Element& e : out) e.set_laser(element.laser());
  return out;
}

}  // namespace mark
