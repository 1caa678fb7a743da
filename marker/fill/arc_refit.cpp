#include "marker/fill/arc_refit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace mark {
namespace {

// What a vertex can lie on: a source line, a source arc, or (for an inset) a source corner,
// whose round join is an arc of radius = the inset about it.
struct Primitive {
  enum Kind { line, arc, corner } kind;
  Point a{0, 0}, b{0, 0};  // line ends; for an arc and a corner, a is the centre
  double radius = 0;       // arc
  double start = 0, sweep = 0;
  Box reach;               // where a matching vertex can be
};

double cross(const Point& u, const Point& v) { return u.x() * v.y() - u.y() * v.x(); }

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Is the direction of p (about the arc's centre) inside the arc's sweep?
bool within_sweep(const Primitive& arc, const Point& p) {
  double phi = std::atan2(p.y() - arc.a.y(), p.x() - arc.a.x()) - arc.start;
  const double two_pi = 2 * std::numbers::pi;
  if (arc.sweep >= 0) {
    phi = std::fmod(std::fmod(phi, two_pi) + two_pi, two_pi);
    return phi <= arc.sweep + 1e-9;
  }
  phi = std::fmod(std::fmod(-phi, two_pi) + two_pi, two_pi);
  return phi <= -arc.sweep + 1e-9;
}

double distance_to(const Primitive& p, const Point& v) {
  switch (p.kind) {
    case Primitive::line: return distance_to_segment(v, p.a, p.b);
    case Primitive::corner: return (v - p.a).norm();
    case Primitive::arc: {
      if (within_sweep(p, v)) return std::abs((v - p.a).norm() - p.radius);
      const Point s = p.a + p.radius * Point(std::cos(p.start), std::sin(p.start));
      const Point e = p.a + p.radius * Point(std::cos(p.start + p.sweep), std::sin(p.start + p.sweep));
      return std::min((v - s).norm(), (v - e).norm());
    }
  }
  return INFINITY;
}

std::vector<Primitive> primitives_of(const std::vector<Element>& sources, double distance, double tol) {
  std::vector<Primitive> out;
  const double grow = distance + tol;
  const auto add = [&](Primitive p, Box box) {
    box.min -= Point(grow, grow);
    box.max += Point(grow, grow);
    p.reach = box;
    out.push_back(p);
  };
  for (const Element& e : sources) {
    if (const auto* l = std::get_if<Line>(&e.geometry())) {
      Box b;
      b.add(l->start);
      b.add(l->end);
      add({Primitive::line, l->start, l->end, 0, 0, 0, {}}, b);
    } else if (const auto* c = std::get_if<CircularArc>(&e.geometry())) {
      add({Primitive::arc, c->center, {0, 0}, c->radius, c->start_angle, c->sweep, {}}, e.bounds());
    }
    // Elliptical arcs (a width factor or italic shear on an outline font) have no exact offset
    // among our elements; their stretch of the loop stays chords.
    if (distance > 0) {
      Box b;
      b.add(e.start());
      add({Primitive::corner, e.start(), {0, 0}, 0, 0, 0, {}}, b);
    }
  }
  return out;
}

bool inside(const Box& b, const Point& p) {
  return p.x() >= b.min.x() && p.x() <= b.max.x() && p.y() >= b.min.y() && p.y() <= b.max.y();
}

struct Fit {
  std::vector<Element> elements;
  double residual = INFINITY;  // largest distance of a run vertex from the fitted element
};

// The run's vertices v[0..] on the circle about `center`: arcs of at most a quarter turn each
// (split at the vertices nearest to equal shares of the turn), so every piece is a
// well-conditioned minor arc through its two end vertices.
std::optional<Fit> fit_arc(const std::vector<Point>& v, const Point& center, double tol) {
  std::vector<double> turned(v.size(), 0.0);  // signed angle turned from v[0] to v[i]
  double radius = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    radius += (v[i] - center).norm();
    if (i > 0) {
      const Point u = v[i - 1] - center, w = v[i] - center;
      turned[i] = turned[i - 1] + std::atan2(cross(u, w), u.dot(w));
    }
  }
  radius /= static_cast<double>(v.size());
  const double sweep = turned.back();
  if (std::abs(sweep) < 1e-9 || radius <= 0) return std::nullopt;
  const auto pieces = static_cast<std::size_t>(std::ceil(std::abs(sweep) / (0.5 * std::numbers::pi)));
  Fit fit;
  fit.residual = 0;
  std::size_t i0 = 0;
  for (std::size_t p = 1; p <= pieces; ++p) {
    std::size_t i1 = v.size() - 1;
    if (p < pieces) {  // the vertex nearest to p/pieces of the turn
      const double target = sweep * static_cast<double>(p) / static_cast<double>(pieces);
      i1 = i0 + 1;
      for (std::size_t k = i0 + 1; k < v.size() - 1; ++k)
        if (std::abs(turned[k] - target) < std::abs(turned[i1] - target)) i1 = k;
    }
    if (i1 <= i0) return std::nullopt;
    const double chord = (v[i1] - v[i0]).norm();
    if (chord <= 0 || std::abs(turned[i1] - turned[i0]) > 0.75 * std::numbers::pi) return std::nullopt;
    const Element e = Element::arc_through(v[i0], v[i1], std::max(radius, 0.5 * chord), sweep > 0);
    const auto& g = std::get<CircularArc>(e.geometry());
    for (std::size_t k = i0; k <= i1; ++k)
      fit.residual = std::max(fit.residual, std::abs((v[k] - g.center).norm() - g.radius));
    fit.elements.push_back(e);
    i0 = i1;
    if (i0 == v.size() - 1) break;
  }
  if (i0 != v.size() - 1 || fit.residual > tol) return std::nullopt;
  return fit;
}

Fit fit_run(const std::vector<Point>& v, const Primitive& p, double tol) {
  if (p.kind == Primitive::line) {
    Fit f;
    f.residual = 0;
    for (const Point& q : v) f.residual = std::max(f.residual, distance_to_segment(q, v.front(), v.back()));
    f.elements.push_back(Element::line(v.front(), v.back()));
    return f;
  }
  if (auto f = fit_arc(v, p.a, tol)) return *f;
  return {};
}

std::vector<Element> chords(const std::vector<Point>& v) {
  std::vector<Element> out;
  for (std::size_t i = 0; i + 1 < v.size(); ++i)
    if ((v[i + 1] - v[i]).norm() > 0) out.push_back(Element::line(v[i], v[i + 1]));
  return out;
}

}  // namespace

std::vector<Element> refit_loop(const std::vector<Point>& loop, const std::vector<Element>& sources,
                                const RefitOptions& o) {
  const std::size_t n = loop.size();
  if (n < 3) return {};
  const std::vector<Primitive> prims = primitives_of(sources, o.distance_mm, o.tolerance_mm);
  const auto matches = [&](const Primitive& p, const Point& v) {
    return inside(p.reach, v) && std::abs(distance_to(p, v) - o.distance_mm) <= o.tolerance_mm;
  };
  // The primitives each vertex lies on.
  std::vector<std::vector<std::size_t>> on(n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < prims.size(); ++k)
      if (matches(prims[k], loop[i])) on[i].push_back(k);
  // The primitives each edge lies on: both ends, and for a curve the midpoint too (a long chord
  // across an arc has ends on it but bows away from it).
  std::vector<std::vector<std::size_t>> edge(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const Point mid = (loop[i] + loop[j]) / 2;
    for (std::size_t k : on[i])
      if (std::find(on[j].begin(), on[j].end(), k) != on[j].end() &&
          (prims[k].kind == Primitive::line ||
           std::abs(distance_to(prims[k], mid) - o.distance_mm) <= 2 * o.tolerance_mm))
        edge[i].push_back(k);
  }
  const auto common = [](std::vector<std::size_t> a, const std::vector<std::size_t>& b) {
    std::erase_if(a, [&](std::size_t k) { return std::find(b.begin(), b.end(), k) == b.end(); });
    return a;
  };
  // Start where a run begins, so no run is cut at the loop's seam.
  std::size_t s = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (common(edge[(i + n - 1) % n], edge[i]).empty()) {
      s = i;
      break;
    }
  std::vector<Element> out;
  for (std::size_t done = 0; done < n;) {
    const std::size_t i = (s + done) % n;
    std::vector<std::size_t> run = edge[i];
    std::size_t len = 1;
    if (!run.empty())
      while (done + len < n) {
        std::vector<std::size_t> next = common(run, edge[(i + len) % n]);
        if (next.empty()) break;
        run = std::move(next);
        ++len;
      }
    std::vector<Point> v;
    for (std::size_t k = 0; k <= len; ++k) v.push_back(loop[(i + k) % n]);
    Fit best;
    for (std::size_t k : run) {
      Fit f = fit_run(v, prims[k], o.tolerance_mm);
      if (f.residual < best.residual) best = std::move(f);
    }
    std::vector<Element> piece = best.residual <= o.tolerance_mm ? std::move(best.elements) : chords(v);
    out.insert(out.end(), piece.begin(), piece.end());
    done += len;
  }
  return out;
}

}  // namespace mark
