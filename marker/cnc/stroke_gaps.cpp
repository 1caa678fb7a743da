#include "marker/cnc/stroke_gaps.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <iterator>

#include "fonts/overloaded.hpp"
#include "fonts/stroke_join.hpp"
#include "marker/cnc/flatten.hpp"

namespace mark {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using RPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using RBox = bg::model::box<RPoint>;

constexpr double kFlattenFraction = 1e-3;  // of the letter height
// Closer than this share of the letter height two strokes touch: fonts draw T-junctions that miss
// the crossbar by up to 9e-4 of the height (QCAD's normal.cxf), which no tool can see.
constexpr double kTouchFraction = 5e-3;
// Square within 5°; curves are flattened in steps of at most 8°, so the bisector of a vertex's
// two segments is the curve's tangent there to well within that.
const double kSquareSin = std::sin(5 * M_PI / 180);
constexpr double kMaxStepShare = 0.0024;  // 1 − cos 4°: the chord tolerance for 8° steps, × radius

// The chord tolerance for one element: the search's, or finer on tight curves so that no step
// turns more than 8°.
double chord_tolerance(const Element& e, double tol) {
  return std::visit(Overloaded{[&](const Line&) { return tol; },
                               [&](const CircularArc& a) { return std::min(tol, kMaxStepShare * a.radius); },
                               [&](const EllipticalArc& el) {
                                 // The tightest curvature of an ellipse: b²/a.
                                 const double lo = std::min(el.rx, el.ry), hi = std::max(el.rx, el.ry);
                                 return std::min(tol, kMaxStepShare * lo * lo / std::max(hi, 1e-300));
                               }},
                    e.geometry());
}
// Two points of one stroke whose way along it is shorter than this many times their distance
// are neighbours on the stroke (a bend, a corner), not a gap across it. The sides of an 'O' are
// π/2 ≈ 1.57 times their distance apart along it.
constexpr double kSameStrokeDetour = 1.2;

struct Seg {
  Point a, b;
  std::size_t stroke = 0;
  double s0 = 0;          // arc length of a along its stroke
  bool free_a = false;    // a / b is a free end of an open stroke (or the stroke is a point)
  bool free_b = false;
  Point dir_before_a{0, 0};  // unit direction of the segment before a (interior vertices)
  Point dir_after_b{0, 0};
};

struct StrokeInfo {
  double length = 0;
  bool closed = false;
};

// Closest points of segments p0p1 and q0q1: parameters s, t in [0, 1].
void closest_params(const Point& p0, const Point& p1, const Point& q0, const Point& q1, double& s, double& t) {
  const Point d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  if (a <= 0 && e <= 0) {
    s = t = 0;
    return;
  }
  if (a <= 0) {
    s = 0;
    t = std::clamp(f / e, 0.0, 1.0);
    return;
  }
  const double c = d1.dot(r);
  if (e <= 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
    return;
  }
  const double b = d1.dot(d2), denom = a * e - b * b;
  s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
}

// Whether the point at parameter u of `seg` faces `other` across a gap: the line between them
// leaves the stroke squarely — inside a segment the closest point always does; at a vertex of
// a flattened curve, square (within 5°) to the curve's tangent there (the bisector of its two
// segments); at a corner, within its normal cone (moving along either segment brings it no
// closer); at a free end, moving inwards brings it no closer. Square covers the sides of an 'O'
// (across its diameter the distance is largest, not least); the 5° keeps out the wedge where
// two strokes touch tangentially (a 'B' bowl leaving its crossbar), whose pairs are square only
// where they are closer than the touching distance.
bool faces(const Seg& seg, double u, const Point& here, const Point& other) {
  if (u > 0 && u < 1) return true;
  const Point away = here - other;
  const double len = away.norm();
  if (len <= 0) return false;
  const Point fwd = (seg.b - seg.a).normalized();
  const Point inward = u <= 0 ? fwd : Point(-fwd);
  const bool free_end = u <= 0 ? seg.free_a : seg.free_b;
  const Point outward = u <= 0 ? Point(-seg.dir_before_a) : seg.dir_after_b;
  const auto not_closer = [&](const Point& dir) { return dir.norm() == 0 || away.dot(dir) >= 0; };
  if (free_end) return not_closer(inward);
  if (not_closer(inward) && not_closer(outward)) return true;
  const Point tangent = (fwd + (u <= 0 ? seg.dir_before_a : seg.dir_after_b)).normalized();
  return std::abs(away.dot(tangent)) <= kSquareSin * len;
}

}  // namespace

std::optional<StrokeGap> narrowest_stroke_gap(const Figure& figure, double up_to_mm, const Progress& progress) {
  const double join_tol = figure.join_tolerance_mm();
  const double height = figure.letter_height_mm > 0 ? figure.letter_height_mm : figure.bounds().height();
  const double flat_tol = std::max(kFlattenFraction * height, 1e-6);
  const double touch = std::max(kTouchFraction * height, join_tol);

  std::vector<Seg> segs;
  std::vector<StrokeInfo> strokes;
  for (const PlacedGlyph& g : figure.glyphs) {
    for (const ChainedStroke& st : chain_strokes(g.elements, join_tol)) {
      const std::size_t id = strokes.size();
      StrokeInfo info;
      info.closed = st.closed(join_tol);
      std::vector<Point> pts;
      for (const Element& e : st.elements) {
        const std::vector<Point> piece = flatten_element(e, std::max(chord_tolerance(e, flat_tol), 1e-9));
        pts.insert(pts.end(), pts.empty() ? piece.begin() : piece.begin() + 1, piece.end());
      }
      const std::size_t first = segs.size();
      if (pts.size() == 1) pts.push_back(pts.front());
      for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
        Seg s;
        s.a = pts[k];
        s.b = pts[k + 1];
        s.stroke = id;
        s.s0 = info.length;
        info.length += (s.b - s.a).norm();
        segs.push_back(s);
      }
      const std::size_t last = segs.size() - 1;
      for (std::size_t k = first; k <= last; ++k) {
        if (k > first) segs[k].dir_before_a = (segs[k - 1].b - segs[k - 1].a).normalized();
        if (k < last) segs[k].dir_after_b = (segs[k + 1].b - segs[k + 1].a).normalized();
      }
      info.closed = info.closed && info.length > join_tol;  // a point is a free end, not a loop
      if (info.closed) {
        segs[first].dir_before_a = (segs[last].b - segs[last].a).normalized();
        segs[last].dir_after_b = (segs[first].b - segs[first].a).normalized();
      } else {
        segs[first].free_a = segs[last].free_b = true;
      }
      strokes.push_back(info);
    }
  }

  std::vector<std::pair<RBox, std::size_t>> boxes;
  boxes.reserve(segs.size());
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const Seg& s = segs[k];
    boxes.push_back({RBox(RPoint(std::min(s.a.x(), s.b.x()), std::min(s.a.y(), s.b.y())),
                          RPoint(std::max(s.a.x(), s.b.x()), std::max(s.a.y(), s.b.y()))),
                     k});
  }
  const bgi::rtree<std::pair<RBox, std::size_t>, bgi::rstar<16>> tree(boxes.begin(), boxes.end());

  std::optional<StrokeGap> best;
  double limit = up_to_mm;
  std::vector<std::pair<RBox, std::size_t>> near;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    if (i % 1024 == 0) progress.step("gcode: measuring gaps between strokes", i, segs.size());
    const Seg& p = segs[i];
    const RBox& b = boxes[i].first;
    near.clear();
    tree.query(bgi::intersects(RBox(RPoint(b.min_corner().get<0>() - limit, b.min_corner().get<1>() - limit),
                                    RPoint(b.max_corner().get<0>() + limit, b.max_corner().get<1>() + limit))),
               std::back_inserter(near));
    for (const auto& [box, j] : near) {
      if (j <= i) continue;
      const Seg& q = segs[j];
      double u = 0, v = 0;
      closest_params(p.a, p.b, q.a, q.b, u, v);
      const Point x = p.a + u * (p.b - p.a), y = q.a + v * (q.b - q.a);
      const double d = (x - y).norm();
      if (d <= touch || d > limit) continue;
      if (p.stroke == q.stroke) {
        const StrokeInfo& st = strokes[p.stroke];
        double along = std::abs((q.s0 + v * (q.b - q.a).norm()) - (p.s0 + u * (p.b - p.a).norm()));
        if (st.closed) along = std::min(along, st.length - along);
        if (along < kSameStrokeDetour * d) continue;
      }
      if (!faces(p, u, x, y) || !faces(q, v, y, x)) continue;
      limit = d;
      best = StrokeGap{d, x, y};
    }
  }
  return best;
}

}  // namespace mark
