#include "marker/cnc/stroke_gaps.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <iterator>
#include <map>
#include <tuple>

#include "fonts/overloaded.hpp"
#include "fonts/stroke_join.hpp"
#include "marker/geometry/flatten.hpp"

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

// One letter's strokes flattened into segments, in its own frame, with an R-tree of their boxes.
struct LetterSegs {
  std::vector<Seg> segs;
  std::vector<StrokeInfo> strokes;
  Box box;
  bgi::rtree<std::pair<RBox, std::size_t>, bgi::rstar<16>> tree;
};

RBox box_of(const Seg& s, double grow) {
  return RBox(RPoint(std::min(s.a.x(), s.b.x()) - grow, std::min(s.a.y(), s.b.y()) - grow),
              RPoint(std::max(s.a.x(), s.b.x()) + grow, std::max(s.a.y(), s.b.y()) + grow));
}

LetterSegs letter_segs(const std::vector<Element>& elements, double join_tol, double flat_tol) {
  LetterSegs out;
  std::vector<Seg>& segs = out.segs;
  for (const ChainedStroke& st : chain_strokes(elements, join_tol)) {
    const std::size_t id = out.strokes.size();
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
      Seg sg;
      sg.a = pts[k];
      sg.b = pts[k + 1];
      sg.stroke = id;
      sg.s0 = info.length;
      info.length += (sg.b - sg.a).norm();
      segs.push_back(sg);
      out.box.add(sg.a);
      out.box.add(sg.b);
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
    out.strokes.push_back(info);
  }
  std::vector<std::pair<RBox, std::size_t>> boxes;
  for (std::size_t k = 0; k < segs.size(); ++k) boxes.push_back({box_of(segs[k], 0), k});
  out.tree = decltype(out.tree)(boxes.begin(), boxes.end());
  return out;
}

// A letter's segments moved into another frame (directions rotate with them).
std::vector<Seg> moved(const std::vector<Seg>& segs, const Affine& t) {
  std::vector<Seg> out = segs;
  for (Seg& sg : out) {
    sg.a = t * sg.a;
    sg.b = t * sg.b;
    sg.dir_before_a = t.linear() * sg.dir_before_a;
    sg.dir_after_b = t.linear() * sg.dir_after_b;
  }
  return out;
}

// The narrowest gap no wider than `limit` between the segments `others` (in `letter`'s frame)
// and `letter`'s own, or — with `others` null — within `letter`, its strokes facing themselves.
std::optional<StrokeGap> narrowest(const LetterSegs& letter, const std::vector<Seg>* others, double limit,
                                   double touch) {
  std::optional<StrokeGap> best;
  const std::vector<Seg>& from = others ? *others : letter.segs;
  std::vector<std::pair<RBox, std::size_t>> near;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const Seg& p = from[i];
    near.clear();
    letter.tree.query(bgi::intersects(box_of(p, limit)), std::back_inserter(near));
    for (const auto& [box, j] : near) {
      if (!others && j <= i) continue;
      const Seg& q = letter.segs[j];
      double u = 0, v = 0;
      closest_params(p.a, p.b, q.a, q.b, u, v);
      const Point x = p.a + u * (p.b - p.a), y = q.a + v * (q.b - q.a);
      const double d = (x - y).norm();
      if (d <= touch || d > limit) continue;
      if (!others && p.stroke == q.stroke) {
        const StrokeInfo& st = letter.strokes[p.stroke];
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

// Where one glyph lies relative to another, rounded (1 nm, 1e-12 rad): pairs of letters that
// stand the same way to each other — every "he" of a text in rows — are measured once.
using PairKey = std::tuple<std::size_t, std::size_t, long long, long long, long long>;

}  // namespace

std::optional<StrokeGap> narrowest_stroke_gap(const Figure& figure, double up_to_mm, const Progress& progress) {
  const double join_tol = figure.join_tolerance_mm();
  const double height = figure.letter_height_mm > 0 ? figure.letter_height_mm : figure.bounds().height();
  const double flat_tol = std::max(kFlattenFraction * height, 1e-6);
  const double touch = std::max(kTouchFraction * height, join_tol);

  // Each distinct letter once, in its own frame: a glyph whose shape the Figure does not hold
  // (a figure built by hand) is a letter of its own, in the field frame.
  std::vector<LetterSegs> letters;
  std::vector<std::size_t> letter_of(figure.glyphs.size());
  std::vector<Affine> frame(figure.glyphs.size(), Affine::Identity());
  std::map<std::size_t, std::size_t> of_shape;
  for (std::size_t g = 0; g < figure.glyphs.size(); ++g) {
    const PlacedGlyph& pg = figure.glyphs[g];
    const bool shaped = pg.shape < figure.shapes.size() && figure.shapes[pg.shape].code_point == pg.code_point &&
                        !figure.shapes[pg.shape].elements.empty();
    if (shaped) {
      frame[g] = pg.placement();
      auto [it, fresh] = of_shape.emplace(pg.shape, letters.size());
      if (fresh) letters.push_back(letter_segs(figure.shapes[pg.shape].elements, join_tol, flat_tol));
      letter_of[g] = it->second;
    } else {
      letter_of[g] = letters.size();
      letters.push_back(letter_segs(pg.elements, join_tol, flat_tol));
    }
  }

  std::optional<StrokeGap> best;
  double limit = up_to_mm;
  const auto keep = [&](const std::optional<StrokeGap>& g, const Affine& to_field) {
    if (!g || g->width_mm > limit) return;
    limit = g->width_mm;
    best = StrokeGap{g->width_mm, to_field * g->a, to_field * g->b};
  };
  // Within each letter (its strokes facing each other), once per distinct letter.
  std::vector<bool> measured(letters.size(), false);
  for (std::size_t g = 0; g < figure.glyphs.size(); ++g) {
    if (measured[letter_of[g]]) continue;
    measured[letter_of[g]] = true;
    keep(narrowest(letters[letter_of[g]], nullptr, limit, touch), frame[g]);
  }
  // Between neighbouring glyphs: pairs whose boxes come within the tool of each other, each
  // distinct relative placement once.
  std::vector<std::pair<RBox, std::size_t>> boxes;
  for (std::size_t g = 0; g < figure.glyphs.size(); ++g) {
    const Box& b = letters[letter_of[g]].box;
    if (b.empty()) continue;
    Box placed;
    for (const Point& c : {b.min, b.max, Point(b.min.x(), b.max.y()), Point(b.max.x(), b.min.y())})
      placed.add(frame[g] * c);
    boxes.push_back({RBox(RPoint(placed.min.x(), placed.min.y()), RPoint(placed.max.x(), placed.max.y())), g});
  }
  const bgi::rtree<std::pair<RBox, std::size_t>, bgi::rstar<16>> glyphs(boxes.begin(), boxes.end());
  std::map<PairKey, std::optional<StrokeGap>> seen;  // in the first glyph's frame
  std::vector<std::pair<RBox, std::size_t>> near;
  for (const auto& [box, g] : boxes) {
    if (g % 256 == 0) progress.step("gcode: measuring gaps between strokes, glyph", g, figure.glyphs.size());
    near.clear();
    const RBox grown(RPoint(box.min_corner().get<0>() - up_to_mm, box.min_corner().get<1>() - up_to_mm),
                     RPoint(box.max_corner().get<0>() + up_to_mm, box.max_corner().get<1>() + up_to_mm));
    glyphs.query(bgi::intersects(grown), std::back_inserter(near));
    for (const auto& [other_box, h] : near) {
      if (h <= g) continue;
      const Affine rel = frame[g].inverse() * frame[h];  // h's frame → g's
      const double angle = std::atan2(rel.linear()(1, 0), rel.linear()(0, 0));
      const PairKey key{letter_of[g], letter_of[h], std::llround(rel.translation().x() * 1e6),
                        std::llround(rel.translation().y() * 1e6), std::llround(angle * 1e12)};
      auto it = seen.find(key);
      if (it == seen.end()) {
        const std::vector<Seg> other = moved(letters[letter_of[h]].segs, rel);
        it = seen.emplace(key, narrowest(letters[letter_of[g]], &other, up_to_mm, touch)).first;
      }
      keep(it->second, frame[g]);
    }
  }
  return best;
}

}  // namespace mark
