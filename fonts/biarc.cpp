// Biarc fitting of cubic Béziers (see biarc.hpp for the method and its references).
#include "fonts/biarc.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "base/numbers.hpp"

namespace mark {
namespace {

// Pieces are halved at most this often: 2^-14 of a glyph curve is far below any tolerance that
// makes sense, so hitting the limit means a degenerate curve, not a real shape.
constexpr int kMaxDepth = 14;
// Samples per piece when measuring the error. The error of a biarc against an inflection-free
// piece is a smooth function with a few humps, so 32 samples find its maximum to well within
// the acceptance margin below.
constexpr int kCurveSamples = 32;
constexpr int kArcSamples = 8;
// A fit is accepted when its sampled error is within this fraction of the tolerance: the margin
// covers the maximum falling between samples.
constexpr double kAcceptFraction = 0.9;

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }

double distance_to_segment(const Point& a, const Point& b, const Point& p) {
  const Point ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// First usable direction among the candidates, normalised; nullopt if all are degenerate.
std::optional<Point> direction(std::initializer_list<Point> candidates, double eps) {
  for (const Point& d : candidates)
    if (d.norm() > eps) return d.normalized();
  return std::nullopt;
}

// The circular arc leaving `p` along unit tangent `t` and ending at `q` (a line if it is straight
// to within `flat`). Nothing if p and q coincide.
std::optional<Element> arc_from_tangent(const Point& p, const Point& t, const Point& q,
                                        double flat) {
  const Point chord = q - p;
  const double len = chord.norm();
  if (len == 0) return std::nullopt;
  const double c = cross(t, chord);
  const double sweep = 2 * std::atan2(c, t.dot(chord));
  // Sagitta of the arc over its chord; tiny sweeps are lines (and avoid huge radii).
  const double sagitta = len / 2 * std::abs(std::tan(sweep / 4));
  if (sagitta <= flat && std::abs(sweep) < kPi) return Element::line(p, q);
  const double signed_radius = chord.squaredNorm() / (2 * c);
  const Point center = p + Point(-t.y(), t.x()) * signed_radius;
  const Point from = p - center;
  return Element::arc(center, std::abs(signed_radius), std::atan2(from.y(), from.x()), sweep);
}

struct Biarc {
  std::array<std::optional<Element>, 2> arcs;
};

// The biarc with equal tangent lengths d from p0 along t0 and into p1 along t1 (Bolton): the join
// point is the midpoint of the two tangent ends, which lies on the incircle-like locus of joins.
std::optional<Biarc> equal_tangent_biarc(const Point& p0, const Point& t0, const Point& p1,
                                         const Point& t1, double flat) {
  const Point v = p1 - p0;
  const Point t = t0 + t1;
  const double vt = v.dot(t);
  const double a = 2 * (t0.dot(t1) - 1);  // t·t − 4, ≤ 0
  double d;
  if (std::abs(a) < 1e-12) {
    if (vt <= 0) return std::nullopt;
    d = v.squaredNorm() / (2 * vt);
  } else {
    d = (vt - std::sqrt(vt * vt - a * v.squaredNorm())) / a;
  }
  if (!std::isfinite(d) || d <= 0) return std::nullopt;
  const Point join = ((p0 + d * t0) + (p1 - d * t1)) / 2;
  Biarc b;
  b.arcs[0] = arc_from_tangent(p0, t0, join, flat);
  // The second arc runs from the join to p1 arriving along t1: fit it backwards and reverse.
  if (auto back = arc_from_tangent(p1, -t1, join, flat)) b.arcs[1] = back->reversed();
  return b;
}

double distance_to_biarc(const Biarc& b, const Point& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& e : b.arcs)
    if (e) best = std::min(best, distance_to_element(*e, p));
  return best;
}

// Largest distance between the biarc and the curve, both ways, by sampling; stops early once
// `limit` is exceeded.
double biarc_error(const CubicBezier& c, const Biarc& b, double limit) {
  std::array<Point, kCurveSamples + 1> samples;
  double worst = 0;
  for (int i = 0; i <= kCurveSamples; ++i) {
    samples[i] = c.point_at(static_cast<double>(i) / kCurveSamples);
    worst = std::max(worst, distance_to_biarc(b, samples[i]));
    if (worst > limit) return worst;
  }
  for (const auto& e : b.arcs) {
    if (!e) continue;
    for (int j = 1; j < kArcSamples; ++j) {
      const Point q = e->point_at(static_cast<double>(j) / kArcSamples);
      // Nearest curve sample, then golden-section search on the two intervals around it.
      int k = 0;
      double dk = std::numeric_limits<double>::infinity();
      for (int i = 0; i <= kCurveSamples; ++i) {
        const double di = (samples[i] - q).squaredNorm();
        if (di < dk) dk = di, k = i;
      }
      // Newton on (B(t) − q)·B'(t) = 0 from the nearest sample; taking the smaller of the two
      // distances keeps the measure an upper bound even if Newton wanders.
      double t = static_cast<double>(k) / kCurveSamples;
      for (int it = 0; it < 4; ++it) {
        const Point r = c.point_at(t) - q, d1 = c.derivative_at(t);
        const Point d2 = 6 * ((1 - t) * (c.p2 - 2 * c.p1 + c.p0) + t * (c.p3 - 2 * c.p2 + c.p1));
        const double slope = d1.squaredNorm() + r.dot(d2);
        if (!(slope > 0)) break;
        t = std::clamp(t - r.dot(d1) / slope, 0.0, 1.0);
      }
      const double dist = std::min(std::sqrt(dk), (c.point_at(t) - q).norm());
      worst = std::max(worst, dist);
      if (worst > limit) return worst;
    }
  }
  return worst;
}

double extent(const CubicBezier& c) {
  double m = 0;
  for (const Point& p : {c.p1, c.p2, c.p3}) m = std::max(m, (p - c.p0).cwiseAbs().maxCoeff());
  return m;
}

void fit_piece(const CubicBezier& c, double tolerance, int depth, std::vector<Element>& out, std::size_t max_out) {
  if (out.size() >= max_out) return;
  const double size = extent(c);
  if (size == 0) return;
  const double eps = size * 1e-12;
  const auto t0 = direction({c.p1 - c.p0, c.p2 - c.p0, c.p3 - c.p0}, eps);
  const auto t1 = direction({c.p3 - c.p2, c.p3 - c.p1, c.p3 - c.p0}, eps);
  const double flat = tolerance * 1e-3;
  std::optional<Biarc> b;
  if (t0 && t1) b = equal_tangent_biarc(c.p0, *t0, c.p3, *t1, flat);
  const bool last_chance = depth >= kMaxDepth;
  if (b && (last_chance || biarc_error(c, *b, tolerance * kAcceptFraction) <=
                               tolerance * kAcceptFraction)) {
    for (const auto& e : b->arcs)
      if (e) out.push_back(*e);
    return;
  }
  if (last_chance) {
    if ((c.p3 - c.p0).norm() > 0) out.push_back(Element::line(c.p0, c.p3));
    return;
  }
  const auto [left, right] = c.split(0.5);
  fit_piece(left, tolerance, depth + 1, out, max_out);
  fit_piece(right, tolerance, depth + 1, out, max_out);
}

}  // namespace

Point CubicBezier::point_at(double t) const {
  const double s = 1 - t;
  return s * s * s * p0 + 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t * p3;
}

Point CubicBezier::derivative_at(double t) const {
  const double s = 1 - t;
  return 3 * (s * s * (p1 - p0) + 2 * s * t * (p2 - p1) + t * t * (p3 - p2));
}

std::pair<CubicBezier, CubicBezier> CubicBezier::split(double t) const {
  const Point a = p0 + t * (p1 - p0), b = p1 + t * (p2 - p1), c = p2 + t * (p3 - p2);
  const Point ab = a + t * (b - a), bc = b + t * (c - b);
  const Point m = ab + t * (bc - ab);
  return {CubicBezier{p0, a, ab, m}, CubicBezier{m, bc, c, p3}};
}

CubicBezier CubicBezier::from_quadratic(const Point& p0, const Point& control, const Point& p2) {
  return {p0, p0 + 2.0 / 3.0 * (control - p0), p2 + 2.0 / 3.0 * (control - p2), p2};
}

std::vector<double> inflections(const CubicBezier& c) {
  // B(t) = a t³ + b t² + c1 t + p0; B'×B'' = −6(a×b) t² + 6(c1×a) t + 2(c1×b).
  const Point a = -c.p0 + 3 * c.p1 - 3 * c.p2 + c.p3;
  const Point b = 3 * c.p0 - 6 * c.p1 + 3 * c.p2;
  const Point c1 = 3 * (c.p1 - c.p0);
  const double qa = -6 * cross(a, b), qb = 6 * cross(c1, a), qc = 2 * cross(c1, b);
  const double scale = std::max({std::abs(qa), std::abs(qb), std::abs(qc)});
  std::vector<double> roots;
  if (scale == 0) return roots;
  if (std::abs(qa) <= 1e-12 * scale) {
    if (std::abs(qb) > 1e-12 * scale) roots.push_back(-qc / qb);
  } else {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0) {
      // Numerically stable pair of roots.
      const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      roots.push_back(q / qa);
      if (q != 0) roots.push_back(qc / q);
    }
  }
  std::vector<double> inside;
  for (double r : roots)
    if (r > 1e-9 && r < 1 - 1e-9) inside.push_back(r);
  std::sort(inside.begin(), inside.end());
  if (inside.size() == 2 && inside[1] - inside[0] < 1e-9) inside.pop_back();
  return inside;
}

double distance_to_cubic(const CubicBezier& c, const Point& p) {
  constexpr int n = 256;
  int k = 0;
  double dk = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) {
    const double di = (c.point_at(double(i) / n) - p).squaredNorm();
    if (di < dk) dk = di, k = i;
  }
  double lo = std::max(0, k - 1) / double(n), hi = std::min(n, k + 1) / double(n);
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 60; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if ((c.point_at(m1) - p).squaredNorm() < (c.point_at(m2) - p).squaredNorm())
      hi = m2;
    else
      lo = m1;
  }
  return std::min(std::sqrt(dk), (c.point_at((lo + hi) / 2) - p).norm());
}

double distance_to_element(const Element& e, const Point& p) {
  if (const auto* l = std::get_if<Line>(&e.geometry())) return distance_to_segment(l->start, l->end, p);
  if (const auto* a = std::get_if<CircularArc>(&e.geometry())) {
    const Point d = p - a->center;
    if (angle_on_sweep(std::atan2(d.y(), d.x()), a->start_angle, a->sweep))
      return std::abs(d.norm() - a->radius);
    return std::min((p - e.start()).norm(), (p - e.end()).norm());
  }
  // Elliptical arcs never come out of the fitter; measure them by sampling for completeness.
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 1024; ++i) best = std::min(best, (e.point_at(i / 1024.0) - p).norm());
  return best;
}

bool fit_biarcs(const CubicBezier& c, double tolerance, std::vector<Element>& out, std::size_t max_out) {
  double from = 0;
  CubicBezier rest = c;
  for (double t : inflections(c)) {
    const auto [piece, tail] = rest.split((t - from) / (1 - from));
    fit_piece(piece, tolerance, 0, out, max_out);
    rest = tail;
    from = t;
  }
  fit_piece(rest, tolerance, 0, out, max_out);
  return out.size() < max_out;
}

}  // namespace mark
