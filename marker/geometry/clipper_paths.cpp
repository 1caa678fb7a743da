#include "marker/geometry/clipper_paths.hpp"

#include <cmath>

#include "marker/geometry/flatten.hpp"

namespace mark {

using namespace ClipperLib;

IntPoint to_nm(const Point& p) {
  return IntPoint(static_cast<cInt>(std::llround(p.x() * kNmPerMm)),
                  static_cast<cInt>(std::llround(p.y() * kNmPerMm)));
}

Point to_mm(const IntPoint& p) {
  return Point(static_cast<double>(p.X) / kNmPerMm, static_cast<double>(p.Y) / kNmPerMm);
}

std::vector<Point> to_mm(const Path& path) {
  std::vector<Point> pts;
  pts.reserve(path.size());
  for (const IntPoint& p : path) pts.push_back(to_mm(p));
  return pts;
}

void append_glyph_polylines(const PlacedGlyph& g, double chord_tol_mm, Paths& out) {
  bool open = false;
  for (const Element& e : g.elements) {
    if (!e.laser()) {
      open = false;
      continue;
    }
    const std::vector<Point> pts = flatten_element(e, chord_tol_mm);
    const IntPoint first = to_nm(pts.front());
    if (!open || out.back().back() != first) out.emplace_back(1, first);
    for (std::size_t k = 1; k < pts.size(); ++k) {
      const IntPoint q = to_nm(pts[k]);
      if (q != out.back().back()) out.back().push_back(q);
    }
    open = true;
  }
}

Paths stroke_polylines(const Figure& figure, double chord_tol_mm) {
  Paths out;
  for (const PlacedGlyph& g : figure.glyphs) append_glyph_polylines(g, chord_tol_mm, out);
  return out;
}

Path loop_polygon(const std::vector<Element>& loop, double chord_tol_mm) {
  Path p;
  for (const Element& e : loop) {
    const std::vector<Point> pts = flatten_element(e, chord_tol_mm);
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {  // the next element starts on the end
      const IntPoint q = to_nm(pts[k]);
      if (p.empty() || p.back() != q) p.push_back(q);
    }
  }
  return p;
}

Paths union_polygons(const Paths& polygons, bool even_odd) {
  const PolyFillType type = even_odd ? pftEvenOdd : pftNonZero;
  Clipper c;
  c.StrictlySimple(true);
  c.AddPaths(polygons, ptSubject, true);
  Paths out;
  c.Execute(ctUnion, out, type, type);
  return out;
}

namespace {
// Round-joined offset by delta (mm) of open strokes or closed regions, in nanometres.
Paths round_offset(const Paths& paths, EndType ends, double delta_mm, double arc_tol_mm) {
  ClipperOffset co(2.0, arc_tol_mm * kNmPerMm);
  co.AddPaths(paths, jtRound, ends);
  Paths out;
  co.Execute(out, delta_mm * kNmPerMm);
  return out;
}
}  // namespace

Paths grow_strokes(const Paths& strokes, double radius_mm, double arc_tol_mm) {
  return round_offset(strokes, etOpenRound, radius_mm, arc_tol_mm);
}

Paths offset_region(const Paths& region, double delta_mm, double arc_tol_mm) {
  return round_offset(region, etClosedPolygon, delta_mm, arc_tol_mm);
}

namespace {
Paths boolean(ClipType op, const Paths& a, const Paths& b) {
  Clipper c;
  c.AddPaths(a, ptSubject, true);
  c.AddPaths(b, ptClip, true);
  Paths out;
  c.Execute(op, out, pftNonZero, pftNonZero);
  return out;
}
}  // namespace

Paths difference(const Paths& a, const Paths& b) { return boolean(ctDifference, a, b); }
Paths intersection(const Paths& a, const Paths& b) { return boolean(ctIntersection, a, b); }

double area_mm2(const Paths& region) {
  double a = 0;
  for (const Path& p : region) a += Area(p);
  return a / (kNmPerMm * kNmPerMm);
}

bool contains(const Paths& region, const Point& p) {
  const IntPoint q = to_nm(p);
  int inside = 0;
  for (const Path& path : region) {
    const int r = PointInPolygon(q, path);
    if (r < 0) return true;  // on a boundary
    inside ^= r;
  }
  return inside != 0;
}

namespace {
// Do segments ab and cd cross at a point inside both (touching does not count)?
bool crosses(const Point& a, const Point& b, const Point& c, const Point& d) {
  auto side = [](const Point& p, const Point& q, const Point& r) {
    return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
  };
  const double d1 = side(a, b, c), d2 = side(a, b, d), d3 = side(c, d, a), d4 = side(c, d, b);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

}  // namespace

bool segment_inside(const Paths& region, const Point& a, const Point& b) {
  if (!contains(region, (a + b) / 2)) return false;
  for (const Path& path : region)
    for (std::size_t k = 0; k < path.size(); ++k)
      if (crosses(a, b, to_mm(path[k]), to_mm(path[(k + 1) % path.size()]))) return false;
  return true;
}

Path rectangle_nm(const Box& b) {
  return {to_nm(b.min), to_nm(Point(b.max.x(), b.min.y())), to_nm(b.max), to_nm(Point(b.min.x(), b.max.y()))};
}

}  // namespace mark
