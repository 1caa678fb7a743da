#include "marker/cnc/vcarve.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "base/error.hpp"
#include "fonts/stroke_font.hpp"
#include "fonts/stroke_join.hpp"
#include "marker/cnc/pocket.hpp"
#include "marker/geometry/clipper_paths.hpp"
#include "marker/order/visit_order.hpp"

namespace mark {
namespace {

using namespace ClipperLib;

// Clipper's round joins for the flat-bottom region, as a share of the tolerance: the polygon
// of an inset lies up to this much inside the true offset curve, so the inset is made deeper by
// it and the V-bit round the flat bottom still never reaches the outline.
constexpr double kArcTolShare = 0.25;
constexpr double kNmRounding_mm = 1e-6;  // outline points rounded to whole nanometres
constexpr int kMaxPasses = 10000;

std::string mm(double v) { return std::to_string(v) + " mm"; }

void validate(const VCarveSettings& v, const CutSettings& cut) {
  if (!(v.bit_angle_deg > 0 && v.bit_angle_deg < 180))
    throw InputError("v-carve: the bit angle must be more than 0 and less than 180 degrees, got " +
                     std::to_string(v.bit_angle_deg));
  if (!(v.tolerance_mm > 0) || !std::isfinite(v.tolerance_mm))
    throw InputError("v-carve: the tolerance must be a positive length, got " + std::to_string(v.tolerance_mm));
  if (!(v.max_depth_mm >= 0) || !(v.flat_bottom_mm >= 0) || !(v.stepover_mm >= 0))
    throw InputError("v-carve: max depth, flat-bottom tool and step-over must not be negative");
  if (v.flat_bottom_mm > 0 && v.stepover_mm > v.flat_bottom_mm / 2)
    throw InputError("v-carve: step-over " + mm(v.stepover_mm) + " is larger than the flat-bottom tool's radius " +
                     mm(v.flat_bottom_mm / 2) + ": the clean-up loops would leave ridges between them");
  if (!(cut.tool_diameter_mm > 0) || !(cut.safe_z_mm > 0) || !(cut.feed_mm_min > 0) || !(cut.plunge_feed_mm_min > 0))
    throw InputError("v-carve: tool diameter, safe Z and feeds must be positive");
}

// Floors of the passes, top down, the last at −limit (one pass without a depth per pass).
std::vector<double> pass_floors(double limit_mm, double per_pass_mm) {
  if (!(per_pass_mm > 0)) return {-limit_mm};
  const double n = std::ceil(limit_mm / per_pass_mm - 1e-9);
  if (n > kMaxPasses)
    throw InputError("v-carve: " + mm(limit_mm) + " deep at " + mm(per_pass_mm) + " per pass needs more than " +
                     std::to_string(kMaxPasses) + " passes");
  std::vector<double> z;
  for (int k = 1; k <= static_cast<int>(n); ++k) z.push_back(-limit_mm * k / n);
  return z;
}

// A letter's lit elements as its area: every stroke must close.
Paths letter_area(const ShapedGlyph& shape, double join_tol, double chord_tol, bool even_odd, bool& curves) {
  Paths polygons;
  curves = false;
  for (const ChainedStroke& st : chain_strokes(shape.elements, join_tol)) {
    if (!st.closed(join_tol)) {
      const Point a = st.start(), b = st.end();
      char where[160];
      std::snprintf(where, sizeof where, " has an open stroke from (%.4f, %.4f) to (%.4f, %.4f) mm", a.x(), a.y(), b.x(),
                    b.y());
      throw InputError("v-carve: " + describe_code_point(shape.code_point) + where +
                       ": v-carving needs closed outlines — an outline font (TTF, OTF) or closed contours");
    }
    for (const Element& e : st.elements) curves = curves || e.kind() != ElementKind::line;
    Path p = loop_polygon(st.elements, chord_tol);
    if (p.size() >= 3) polygons.push_back(std::move(p));
  }
  return union_polygons(polygons, even_odd);
}

struct LetterCut {
  std::vector<std::vector<Eigen::Vector3d>> carve;  // V-bit paths: axis paths, then the flat bottom's edge
  std::vector<PocketLoop> cleanup;                  // end-mill loops
  Paths cleanup_region;                             // where the end mill's centre may go
  double flat_area_mm2 = 0, uncleaned_area_mm2 = 0, deepest_mm = 0;
};

class Carver {
 public:
  Carver(const VCarveSettings& v, double limit_mm)
      : v_(v), tan_(std::tan(v.bit_angle_deg / 2 * std::numbers::pi / 180)), limit_(limit_mm) {}

  double depth(double r, double margin) const { return std::min(std::max(r - margin, 0.0) / tan_, limit_); }

  LetterCut cut(const ShapedGlyph& shape, double join_tol, VCarveLetter& letter, const Progress& progress) const {
    bool curves = false;
    letter.region = letter_area(shape, join_tol, v_.tolerance_mm / 2, v_.even_odd, curves);
    letter.axis = medial_axis(letter.region, v_.tolerance_mm / 2);
    letter.margin_mm = (curves ? v_.tolerance_mm / 2 : 0) + letter.axis.max_radius_excess_mm + kNmRounding_mm;

    LetterCut lc;
    for (const AxisPath& path : letter.axis.paths) {
      std::vector<Eigen::Vector3d> pts;
      for (const AxisSample& s : path) {
        const double d = depth(s.r, letter.margin_mm);
        lc.deepest_mm = std::max(lc.deepest_mm, d);
        pts.emplace_back(s.p.x(), s.p.y(), -d);
      }
      lc.carve.push_back(std::move(pts));
    }
    // Where the cap flattens the carve: the region farther than the cap's radius from the outline.
    const double arc_tol = kArcTolShare * v_.tolerance_mm;
    const double r_cap = limit_ * tan_;
    letter.flat = offset_region(letter.region, -(r_cap + letter.margin_mm + arc_tol), arc_tol);
    lc.flat_area_mm2 = area_mm2(letter.flat);
    for (const Path& ring : letter.flat) {
      std::vector<Eigen::Vector3d> loop;
      for (const IntPoint& q : ring) loop.emplace_back(to_mm(q).x(), to_mm(q).y(), -limit_);
      if (loop.size() < 3) continue;
      loop.push_back(loop.front());
      lc.carve.push_back(std::move(loop));
    }
    lc.uncleaned_area_mm2 = lc.flat_area_mm2;
    if (v_.flat_bottom_mm > 0 && !letter.flat.empty()) {
      const double rm = v_.flat_bottom_mm / 2;
      lc.cleanup_region = offset_region(letter.flat, -(rm + arc_tol), arc_tol);
      const double step = v_.stepover_mm > 0 ? v_.stepover_mm : 0.4 * v_.flat_bottom_mm;
      lc.cleanup = pocket_loops(lc.cleanup_region, step, arc_tol, progress);
      const Paths reached = offset_region(lc.cleanup_region, rm, arc_tol);
      lc.uncleaned_area_mm2 = std::max(0.0, area_mm2(difference(letter.flat, reached)));
    }
    return lc;
  }

 private:
  const VCarveSettings& v_;
  double tan_, limit_;
};

// The visiting item of a carve path: closed loops go round; open paths cut in an even number of
// passes go there and back and leave where they entered.
VisitItem carve_item(const std::vector<Eigen::Vector3d>& path, bool even_passes) {
  const Point a = path.front().head<2>(), b = path.back().head<2>();
  if ((a - b).norm() < 1e-12) return VisitItem::fixed(a, a);
  if (even_passes) return {a, a, true, b, b};
  return VisitItem::stroke(a, b);
}

// The V-bit subprogram of one letter: its paths in an order that keeps rapids short, each in
// every pass (never below the pass's floor); open paths go back and forth between passes, so
// no pass starts with a rapid.
ToolSubprogram carve_subprogram(const LetterCut& lc, const CutSettings& cut, const std::vector<double>& floors,
                                const std::string& label, Point& entry, Point& exit) {
  const bool even = floors.size() % 2 == 0;
  std::vector<VisitItem> items;
  for (const auto& p : lc.carve) items.push_back(carve_item(p, even));
  ToolSubprogram sub;
  sub.label = label;
  bool first = true;
  for (const VisitStep& st : plan_visit_order(items, Point(0, 0))) {
    std::vector<Eigen::Vector3d> path = lc.carve[st.item];
    if (st.reversed) std::reverse(path.begin(), path.end());
    const bool closed = (path.front().head<2>() - path.back().head<2>()).norm() < 1e-12;
    const Point p0 = path.front().head<2>();
    if (first) entry = p0;
    first = false;
    sub.body.push_back(ToolMove::rapid(p0.x(), p0.y(), cut.safe_z_mm));
    for (std::size_t pass = 0; pass < floors.size(); ++pass) {
      if (pass > 0 && !closed) std::reverse(path.begin(), path.end());
      const double floor = floors[pass];
      sub.body.push_back(ToolMove::feed(path[0].x(), path[0].y(), std::max(path[0].z(), floor), cut.plunge_feed_mm_min));
      for (std::size_t k = 1; k < path.size(); ++k)
        sub.body.push_back(ToolMove::feed(path[k].x(), path[k].y(), std::max(path[k].z(), floor), cut.feed_mm_min));
    }
    exit = path.back().head<2>();
    sub.body.push_back(ToolMove::rapid(exit.x(), exit.y(), cut.safe_z_mm));
  }
  return sub;
}

ToolSubprogram cleanup_subprogram(const LetterCut& lc, const CutSettings& cut, const std::vector<double>& floors,
                                  double mill_mm, const std::string& label) {
  ToolSubprogram sub;
  sub.label = label;
  const PocketMoves pm{cut.safe_z_mm, cut.feed_mm_min, cut.plunge_feed_mm_min, 0.8 * mill_mm};
  Point at(0, 0);
  bool at_depth = false;
  for (double z : floors) append_pocket_pass(lc.cleanup, lc.cleanup_region, z, pm, at, at_depth, sub.body);
  sub.body.push_back(ToolMove::rapid(at.x(), at.y(), cut.safe_z_mm));
  return sub;
}

}  // namespace

VCarveResult vcarve_toolpath(const Figure& figure, const CutSettings& cut, const VCarveSettings& v,
                             const Progress& progress) {
  validate(v, cut);
  const double tan_half = std::tan(v.bit_angle_deg / 2 * std::numbers::pi / 180);
  VCarveResult res;
  res.half_angle_rad = v.bit_angle_deg / 2 * std::numbers::pi / 180;
  // The bit's radius at the surface cannot exceed its own radius.
  const double bit_limit = cut.tool_diameter_mm / 2 / tan_half;
  res.depth_limit_mm = v.max_depth_mm > 0 ? std::min(v.max_depth_mm, bit_limit) : bit_limit;
  // The clean-up mills the flat bottoms, at the cap, in passes; each letter's carve goes down in
  // passes to its own deepest point.
  const std::vector<double> cleanup_floors = pass_floors(res.depth_limit_mm, cut.depth_per_pass_mm);
  const double join_tol = figure.join_tolerance_mm();
  const Carver carver(v, res.depth_limit_mm);

  // One carve per distinct character.
  std::map<std::size_t, std::size_t> letter_of_shape;
  std::vector<LetterCut> cuts;
  std::vector<Point> entries, exits;
  for (const PlacedGlyph& g : figure.glyphs) {
    if (letter_of_shape.count(g.shape)) continue;
    const ShapedGlyph& shape = figure.shapes.at(g.shape);
    if (std::none_of(shape.elements.begin(), shape.elements.end(), [](const Element& e) { return e.laser(); }))
      continue;
    progress.step("v-carve: medial axes of the letters", cuts.size(), 0);
    VCarveLetter letter;
    LetterCut lc = carver.cut(shape, join_tol, letter, progress);
    if (lc.carve.empty()) continue;
    res.axis_edges += letter.axis.voronoi_edges;
    res.pruned_edges += letter.axis.pruned_edges;
    res.deepest_mm = std::max(res.deepest_mm, lc.deepest_mm);
    const std::string label = describe_code_point(shape.code_point);
    Point entry(0, 0), exit(0, 0);
    const std::vector<double> floors = pass_floors(std::max(lc.deepest_mm, 1e-6), cut.depth_per_pass_mm);
    res.toolpath.subs.push_back(carve_subprogram(lc, cut, floors, label, entry, exit));
    if (v.flat_bottom_mm > 0)
      res.cleanup.subs.push_back(cleanup_subprogram(lc, cut, cleanup_floors, v.flat_bottom_mm, label + " clean-up"));
    entries.push_back(entry);
    exits.push_back(exit);
    letter_of_shape[g.shape] = cuts.size();
    cuts.push_back(std::move(lc));
    res.letters.push_back(std::move(letter));
  }
  if (cuts.empty()) throw InputError("v-carve: the text has no letters to carve");

  // Occurrences in an order that keeps the rapids between letters short.
  std::vector<SubprogramCall> calls;
  std::vector<VisitItem> items;
  for (const PlacedGlyph& g : figure.glyphs) {
    auto it = letter_of_shape.find(g.shape);
    if (it == letter_of_shape.end()) continue;
    const Affine place = g.placement();
    calls.push_back({it->second, g.origin, g.rotation_rad});
    items.push_back(VisitItem::fixed(place * entries[it->second], place * exits[it->second]));
    res.flat_area_mm2 += cuts[it->second].flat_area_mm2;
    res.uncleaned_area_mm2 += cuts[it->second].uncleaned_area_mm2;
  }
  res.toolpath.safe_z_mm = res.cleanup.safe_z_mm = cut.safe_z_mm;
  for (const VisitStep& step : plan_visit_order(items, items.front().entry, progress)) {
    res.toolpath.steps.push_back(calls[step.item]);
    if (v.flat_bottom_mm > 0 && !cuts[calls[step.item].sub].cleanup.empty())
      res.cleanup.steps.push_back(calls[step.item]);
  }
  return res;
}

}  // namespace mark
