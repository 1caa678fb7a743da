#include "marker/cnc/comp_contours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "marker/cnc/element_distance.hpp"
#include "marker/geometry/clipper_paths.hpp"

namespace mark {
namespace {

// ε: how much rounder than the tool every wall corner is. The corners are polygons, and a
// control meets each chord as a concave corner whose offset must not vanish.
double rounding_mm(double r) { return std::max(0.02, 0.25 * r); }
constexpr double kCleanNm = 2000;
// The polygon wall's chords, the cleaning above and the control's rounding each move the
// compensated tool by a micrometre or two; programming the wall this much into the cleared
// side keeps the tool at least a radius from the letters regardless.
constexpr double kWallInsetMm = 0.004;
constexpr double kChordSlackMm = 0.005;

}  // namespace

std::vector<CompContour> comp_contours(const ClipperLib::Paths& region, double r, double arc_tol,
                                       std::size_t& without_lead) {
  without_lead = 0;
  const double eps = rounding_mm(r);
  ClipperLib::Paths walls =
      offset_region(offset_region(region, -eps, arc_tol), r + eps - kWallInsetMm, arc_tol);
  // Two offsets leave micrometre zigzags; a control sees each as a concave corner too small
  // for the tool. Vertices closer than this to their neighbours' line go.
  ClipperLib::CleanPolygons(walls, kCleanNm);
  std::vector<CompContour> out;
  for (const ClipperLib::Path& path : walls) {
    const std::vector<Point> pts = to_mm(path);
    if (pts.size() < 3) continue;
    // Clipper's outer boundaries run counter-clockwise and holes clockwise: either way the
    // cleared side, where the tool belongs, is on the left.
    std::vector<std::size_t> edges(pts.size());
    std::iota(edges.begin(), edges.end(), 0);
    std::sort(edges.begin(), edges.end(), [&](std::size_t a, std::size_t b) {
      return (pts[(a + 1) % pts.size()] - pts[a]).squaredNorm() > (pts[(b + 1) % pts.size()] - pts[b]).squaredNorm();
    });
    // Enter in the middle of a long edge, approaching at a shallow angle θ from the cleared
    // side. A control turns into a concave corner by pulling the tool back r·tan(turn/2) along
    // both segments, so the half edge must hold the pull-back of the entry and of its far end.
    bool found = false;
    const std::size_t n = pts.size();
    for (std::size_t k = 0; k < std::min<std::size_t>(n, 64) && !found; ++k) {
      const std::size_t e = edges[k];
      const Point a = pts[e], b = pts[(e + 1) % n], c = pts[(e + 2) % n];
      const double half = (b - a).norm() / 2;
      const Point dir = (b - a).normalized(), left(-dir.y(), dir.x());
      const Point next = (c - b).normalized();
      const double turn_b = std::max(0.0, std::atan2(dir.x() * next.y() - dir.y() * next.x(), dir.dot(next)));
      const double room = 0.8 * half / r - std::tan(turn_b / 2);
      if (room <= 0) continue;
      const double theta = std::min(std::numbers::pi / 3, 2 * std::atan(room));
      const Point w0 = (a + b) / 2;
      for (double lead : {1.5, 1.2, 1.05}) {
        const double h = lead * r;
        const Point q = w0 + h * left - (h / std::tan(theta)) * dir;
        // Where the control has the tool after the lead-in and before the lead-out.
        const Point p0 = w0 + (r + kChordSlackMm) * left;
        if (!contains(region, q) || !segment_inside(region, q, p0)) continue;
        CompContour cc;
        cc.lead = q;
        cc.wall.push_back(w0);
        for (std::size_t i = 1; i <= n; ++i) cc.wall.push_back(pts[(e + i) % n]);
        cc.wall.push_back(w0);
        out.push_back(std::move(cc));
        found = true;
        break;
      }
    }
    if (!found) ++without_lead;
  }
  return out;
}

void append_comp_contours(const std::vector<CompContour>& contours, const ClipperLib::Paths& region,
                          double z, const PocketMoves& m, Point& at, bool& at_depth, std::vector<ToolMove>& out) {
  for (const CompContour& c : contours) {
    const Point& q = c.lead;
    if (at_depth && (q - at).norm() <= m.max_link_mm && segment_inside(region, at, q)) {
      out.push_back(ToolMove::feed(q.x(), q.y(), z, m.feed_mm_min));
    } else {
      if (at_depth) out.push_back(ToolMove::rapid(at.x(), at.y(), m.safe_z_mm));
      out.push_back(ToolMove::rapid(q.x(), q.y(), m.safe_z_mm));
      out.push_back(ToolMove::feed(q.x(), q.y(), z, m.plunge_feed_mm_min));
    }
    for (std::size_t k = 0; k < c.wall.size(); ++k) {
      ToolMove mv = ToolMove::feed(c.wall[k].x(), c.wall[k].y(), z, m.feed_mm_min);
      if (k == 0) mv.comp = CompSide::left;
      out.push_back(mv);
    }
    ToolMove exit = ToolMove::feed(q.x(), q.y(), z, m.feed_mm_min);
    exit.comp = CompSide::cancel;
    out.push_back(exit);
    at = q;
    at_depth = true;
  }
}

bool follows_wall(const std::vector<Point>& loop, const CompContour& c, double r) {
  const double lo = r - 0.01, hi = r + rounding_mm(r) + 0.01;
  const std::size_t step = std::max<std::size_t>(1, loop.size() / 8);
  for (std::size_t k = 0; k < loop.size(); k += step) {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < c.wall.size(); ++i) d = std::min(d, distance_to_segment(loop[k], c.wall[i - 1], c.wall[i]));
    if (d < lo || d > hi) return false;
  }
  return true;
}

}  // namespace mark
