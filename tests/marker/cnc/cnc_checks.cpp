#include "cnc_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace mark::test {


const char* name(Dialect d) { return d == Dialect::linuxcnc ? "linuxcnc" : d == Dialect::fanuc ? "fanuc" : "plain"; }
const char* name(Fit f) { return f == Fit::linear ? "linear" : f == Fit::inclined ? "inclined" : "circular"; }
const char* name(Variant v) { return v == Variant::upright ? "upright" : v == Variant::mirrored ? "mirrored" : "sheared"; }

// The interpreter's moves against the Figure. `print_mm`: resolution of rs274's printout.
DepressionCheck check_depression(const Figure& fig, const Rs274Run& run, const CutSettings& s, double print_mm) {
  DepressionCheck c;
  const NearSet strokes = lit_strokes(fig);
  const std::vector<CanonMove> cuts = cutting_moves(run.moves, -1e-6);
  c.cutting_moves = cuts.size();
  for (const CanonMove& m : cuts) {
    if (m.kind == CanonMove::arc) ++c.arcs;
    for (const Point& p : samples(m.path(), 0.02)) {
      const double d = strokes.distance(p, 1.0);
      if (d > kTolMm + print_mm)
        ADD_FAILURE() << "move to " << m.end.transpose() << " (kind " << m.kind << ") passes "
                      << p.transpose() << ", " << d << " mm off the strokes";
      c.worst_off_stroke_mm = std::max(c.worst_off_stroke_mm, d);
    }
  }
  NearSet full_depth;
  for (const CanonMove& m : cuts)
    if (std::abs(m.end.z() + s.depth_mm) < 1e-3) full_depth.add(m.path());
  for (const PlacedGlyph& g : fig.glyphs)
    for (const Element& e : g.elements)
      if (e.laser())
        for (const Point& p : samples(e, 0.05))
          c.worst_uncovered_mm = std::max(c.worst_uncovered_mm, full_depth.distance(p, 1.0));
  // Sideways rapids only at or above the surface.
  for (const CanonMove& m : run.moves)
    if (m.kind == CanonMove::traverse && (m.end.head<2>() - m.start.head<2>()).norm() > 1e-9) {
      EXPECT_GE(m.start.z(), s.safe_z_mm - print_mm);
      EXPECT_GE(m.end.z(), s.safe_z_mm - print_mm);
    }
  double deepest = 0;
  for (const CanonMove& m : run.moves) deepest = std::min(deepest, m.end.z());
  EXPECT_NEAR(deepest, -s.depth_mm, print_mm);
  EXPECT_LE(c.worst_off_stroke_mm, kTolMm + print_mm);
  EXPECT_LE(c.worst_uncovered_mm, kTolMm + print_mm);
  return c;
}

// Checks on a grid of points over the plate (spacing h): a point is cut when a full-depth move
// passes within the tool radius; an uncut point whose distance from every move is at least
// r + ρ, from the letters at least ρ and from the plate edge at least ρ is the centre of a
// disc of radius ρ left standing. With ρ = 0.95 r and h ≤ 0.07 r every leftover region that
// holds a whole tool disc contains such a grid point.
ProtrusionCheck check_protrusion(const Figure& fig, const Rs274Run& run, const CutSettings& s,
                                 const ProtrusionResult& res) {
  ProtrusionCheck c;
  const double r = s.tool_diameter_mm / 2, half_w = res.stroke_width_mm / 2;
  const SegmentGrid strokes = stroke_grid(fig, res.plate, kStrokeChordMm);
  // Distance from the letter region = distance from the strokes − half the stroke width.
  for (const CanonMove& m : run.moves) {
    if (m.start.z() >= 0 && m.end.z() >= 0) continue;
    const double near = half_w + r + 0.1;  // farther is clearly fine
    for (const Point& p : samples(m.path(), 0.02))
      c.closest_to_letters_mm = std::min(c.closest_to_letters_mm, strokes.distance(p, near) - half_w);
  }
  SegmentGrid cuts(res.plate, 0.25);
  for (const CanonMove& m : run.moves) {
    if (std::abs(m.end.z() + s.depth_mm) > 1e-3 || std::abs(m.start.z() + s.depth_mm) > 1e-3) continue;
    if (m.kind != CanonMove::arc) {
      cuts.add(m.start.head<2>(), m.end.head<2>());
      continue;
    }
    const std::vector<Point> pts = samples(m.path(), 0.02);  // chords 0.1 µm inside the arc
    for (std::size_t k = 1; k < pts.size(); ++k) cuts.add(pts[k - 1], pts[k]);
  }
  const double rho = 0.95 * r, h = std::min(0.02, 0.07 * r);
  for (double x = res.plate.min.x() + h / 2; x < res.plate.max.x(); x += h)
    for (double y = res.plate.min.y() + h / 2; y < res.plate.max.y(); y += h) {
      const Point p(x, y);
      if (cuts.any_within(p, r)) continue;
      const double d_cut = cuts.distance(p, r + rho);
      const double d_letters = strokes.distance(p, half_w + rho) - half_w;
      if (d_letters <= 0) continue;
      c.uncut_mm2 += h * h;
      const double d_edge = std::min({x - res.plate.min.x(), res.plate.max.x() - x,
                                      y - res.plate.min.y(), res.plate.max.y() - y});
      if (d_cut >= r + rho && d_letters >= rho && d_edge >= rho) ++c.wider_than_tool;
    }
  return c;
}

}  // namespace mark::test
