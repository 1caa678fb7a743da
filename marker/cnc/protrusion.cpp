#include "marker/cnc/protrusion.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "marker/cnc/comp_contours.hpp"
#include "marker/cnc/pocket.hpp"
#include "marker/geometry/clipper_paths.hpp"

namespace mark {
namespace {

using namespace ClipperLib;

// Polygons approximate round offsets from inside; growing the keep-out by the approximation
// error keeps the tool centre at least a tool radius from the true letter region. Clipper
// rounds the number of steps of a round join, so a short join may bow up to (1.5)² times its
// arc tolerance: hence 3 × the tolerance, plus the chords of the flattened strokes.
constexpr double kKeepOutSlackMm = kChordTolMm + 3 * kArcTolMm;
// Uncut material thinner than this is the film the slack leaves, not a region worth reporting.
constexpr double kUncutFilmMm = 0.02;
// A pocket is cleared in at most this many nested loops (a 1 mm tool at the default step-over
// clears a 800 mm wide plate with it); more would take Clipper minutes and the machine days.
constexpr double kMaxPocketLoops = 1000;

std::string mm_text(double v) {
  std::ostringstream s;
  s << v << " mm";
  return s.str();
}

std::vector<UncutRegion> uncut_regions(const Paths& material, const Paths& cleared, Paths& left) {
  const Paths all = difference(material, cleared);
  // Opening: drop slivers thinner than the film, keep the rest at full size.
  left = intersection(offset_region(offset_region(all, -kUncutFilmMm / 2, kArcTolMm), kUncutFilmMm / 2, kArcTolMm), all);
  std::vector<UncutRegion> out;
  for (const Path& p : left) {
    if (!Orientation(p)) continue;  // holes belong to the region around them
    UncutRegion r;
    r.area_mm2 = std::abs(Area(p)) / (kNmPerMm * kNmPerMm);
    for (const IntPoint& q : p) r.bounds.add(to_mm(q));
    out.push_back(r);
  }
  return out;
}

}  // namespace

ProtrusionResult protrusion_toolpath(const Figure& figure, const CutSettings& s,
                                     const ProtrusionSettings& ps, const Progress& progress) {
  validate(s);
  ProtrusionResult res;
  const double r = s.tool_diameter_mm / 2;
  res.stroke_width_mm = ps.stroke_width_mm > 0 ? ps.stroke_width_mm : s.tool_diameter_mm;
  const double margin = ps.margin_mm > 0 ? ps.margin_mm : 2 * s.tool_diameter_mm;
  res.stepover_mm = ps.stepover_mm > 0 ? ps.stepover_mm : 0.4 * s.tool_diameter_mm;
  if (ps.stroke_width_mm < 0 || ps.margin_mm < 0 || ps.stepover_mm < 0)
    throw InputError("stroke width, margin and step-over must not be negative");
  if (res.stepover_mm > r)
    throw InputError("step-over " + mm_text(res.stepover_mm) + " is larger than the tool radius " + mm_text(r) +
                     ": the pocket loops would leave ridges between them");

  const Paths strokes = stroke_polylines(figure, kChordTolMm);
  if (strokes.empty()) throw InputError("protrusion: the text has no strokes to leave standing");
  progress.step("protrusion: growing the letters", 0, 0);
  res.letters = grow_strokes(strokes, res.stroke_width_mm / 2, kArcTolMm);
  const Paths keep_out = grow_strokes(strokes, res.stroke_width_mm / 2 + r + kKeepOutSlackMm, kArcTolMm);

  for (const Path& p : res.letters)
    for (const IntPoint& q : p) res.plate.add(to_mm(q));
  res.plate.min -= Point(margin, margin);
  res.plate.max += Point(margin, margin);
  Box inset = res.plate;
  inset.min += Point(r, r);
  inset.max -= Point(r, r);
  progress.step("protrusion: the tool-centre region", 0, 0);
  res.tool_region = difference({rectangle_nm(inset)}, keep_out);
  res.cleared = offset_region(res.tool_region, r, kArcTolMm);
  progress.step("protrusion: material the tool cannot reach", 0, 0);
  res.uncut = uncut_regions(difference({rectangle_nm(res.plate)}, res.letters), res.cleared, res.uncut_region);

  // The deepest point of the pocket is at most half the inset plate's shorter side from a wall.
  const double nesting = std::min(inset.width(), inset.height()) / 2 / res.stepover_mm;
  if (nesting > kMaxPocketLoops)
    throw InputError("the pocket around the letters needs up to " + std::to_string(std::lround(nesting)) +
                     " nested loops at a step-over of " + mm_text(res.stepover_mm) + ", more than " +
                     std::to_string(static_cast<int>(kMaxPocketLoops)) +
                     "; raise the step-over or narrow the margin");
  std::vector<PocketLoop> loops = pocket_loops(res.tool_region, res.stepover_mm, kArcTolMm, progress);
  std::vector<CompContour> walls;
  if (ps.cutter_comp) {
    // The walls go to the control as part contours; only the inner loops stay tool-centre paths.
    walls = comp_contours(res.tool_region, r, kArcTolMm, res.walls_without_comp);
    std::erase_if(loops, [&](const PocketLoop& l) {
      if (l.level != 0) return false;
      for (const CompContour& c : walls)
        if (follows_wall(l.points, c, r)) return true;
      return false;
    });
    res.comp_walls = walls.size();
  }
  res.loops = loops.size() + walls.size();
  Toolpath& tp = res.toolpath;
  tp.safe_z_mm = s.safe_z_mm;
  tp.comp_diameter_mm = s.tool_diameter_mm;
  const PocketMoves pm{s.safe_z_mm, s.feed_mm_min, s.plunge_feed_mm_min, 2 * res.stepover_mm};
  std::vector<ToolMove> moves;
  Point at = res.plate.min;
  bool at_depth = false;
  for (double z : pass_depths(s)) {
    append_pocket_pass(loops, res.tool_region, z, pm, at, at_depth, moves, progress);
    append_comp_contours(walls, res.tool_region, z, pm, at, at_depth, moves);
  }
  moves.push_back(ToolMove::rapid(at.x(), at.y(), s.safe_z_mm));
  for (const ToolMove& m : moves) tp.steps.emplace_back(m);
  return res;
}

}  // namespace mark
