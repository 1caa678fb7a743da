#include "marker/cnc/pocket.hpp"

#include <algorithm>
#include <limits>

#include "marker/geometry/clipper_paths.hpp"

namespace mark {
namespace {

using namespace ClipperLib;

constexpr double kInnerArcTolMm = 0.005;
constexpr double kPocketCleanNm = 500;  // drop vertices this close to their neighbours' line

// One connected piece of an eroded region: its outer boundary and holes.
struct Component {
  Path outer;
  Paths holes;
  int level = 0;
  std::vector<std::size_t> children;  // components one level deeper inside this one
};

void collect(const PolyNode& node, int level, std::vector<Component>& out) {
  for (const PolyNode* child : node.Childs) {
    if (child->IsHole()) continue;
    Component c;
    c.outer = child->Contour;
    c.level = level;
    for (const PolyNode* hole : child->Childs) {
      c.holes.push_back(hole->Contour);
      collect(*hole, level, out);  // islands inside holes
    }
    out.push_back(std::move(c));
  }
}

bool inside_component(const Component& c, const IntPoint& p) {
  if (PointInPolygon(p, c.outer) == 0) return false;
  for (const Path& h : c.holes)
    if (PointInPolygon(p, h) == 1) return false;
  return true;
}

void emit_component(std::vector<Component>& comps, std::size_t idx, std::vector<PocketLoop>& out) {
  for (std::size_t child : comps[idx].children) emit_component(comps, child, out);
  out.push_back({to_mm(comps[idx].outer), comps[idx].level});
  for (const Path& h : comps[idx].holes) out.push_back({to_mm(h), comps[idx].level});
}

}  // namespace

std::vector<PocketLoop> pocket_loops(const Paths& region, double stepover_mm, double arc_tol_mm,
                                     const Progress& progress) {
  // Inner loops only need to stay within a step-over of each other, not to hug a wall: they use
  // a coarser arc tolerance, and each level is offset from the previous one (eroding twice by
  // s is eroding by 2s), which keeps every offset small and fast.
  const double inner_tol_mm = std::max(arc_tol_mm, std::min(kInnerArcTolMm, 0.02 * stepover_mm));
  std::vector<Component> comps;
  std::vector<std::size_t> first_of_level;
  Paths level_paths = region;
  for (int level = 0;; ++level) {
    progress.step("pocket: offsetting loops, level", static_cast<std::size_t>(level), 0);
    PolyTree tree;
    if (level == 0) {
      Clipper c;  // the region itself, as a tree of outer boundaries and holes
      c.AddPaths(region, ptSubject, true);
      c.Execute(ctUnion, tree, pftNonZero, pftNonZero);
    } else {
      ClipperOffset co(2.0, inner_tol_mm * kNmPerMm);
      co.AddPaths(level_paths, jtRound, etClosedPolygon);
      co.Execute(tree, -stepover_mm * kNmPerMm);
    }
    const std::size_t before = comps.size();
    collect(tree, level, comps);
    if (comps.size() == before) break;
    first_of_level.push_back(before);
    PolyTreeToPaths(tree, level_paths);
    CleanPolygons(level_paths, kPocketCleanNm);
    // Hang each new component under the component of the previous level that holds it.
    if (level > 0)
      for (std::size_t k = before; k < comps.size(); ++k)
        for (std::size_t p = first_of_level[level - 1]; p < before; ++p)
          if (inside_component(comps[p], comps[k].outer.front())) {
            comps[p].children.push_back(k);
            break;
          }
  }
  std::vector<PocketLoop> out;
  if (first_of_level.empty()) return out;
  const std::size_t level0_end = first_of_level.size() > 1 ? first_of_level[1] : comps.size();
  for (std::size_t k = 0; k < level0_end; ++k) emit_component(comps, k, out);
  return out;
}

void append_pocket_pass(const std::vector<PocketLoop>& loops, const Paths& region, double z,
                        const PocketMoves& m, Point& at, bool& at_depth, std::vector<ToolMove>& out,
                        const Progress& progress) {
  for (std::size_t n = 0; n < loops.size(); ++n) {
    progress.step("pocket: linking loops", n, loops.size());
    const PocketLoop& loop = loops[n];
    if (loop.points.size() < 2) continue;
    // Enter the loop at its vertex nearest to the tool.
    std::size_t start = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < loop.points.size(); ++k) {
      const double d = (loop.points[k] - at).squaredNorm();
      if (d < best) best = d, start = k;
    }
    const Point& p0 = loop.points[start];
    if (at_depth && (p0 - at).norm() <= m.max_link_mm && segment_inside(region, at, p0)) {
      out.push_back(ToolMove::feed(p0.x(), p0.y(), z, m.feed_mm_min));
    } else {
      if (at_depth) out.push_back(ToolMove::rapid(at.x(), at.y(), m.safe_z_mm));
      out.push_back(ToolMove::rapid(p0.x(), p0.y(), m.safe_z_mm));
      out.push_back(ToolMove::feed(p0.x(), p0.y(), z, m.plunge_feed_mm_min));
    }
    for (std::size_t k = 1; k <= loop.points.size(); ++k) {
      const Point& p = loop.points[(start + k) % loop.points.size()];
      out.push_back(ToolMove::feed(p.x(), p.y(), z, m.feed_mm_min));
    }
    at = p0;
    at_depth = true;
  }
}

}  // namespace mark
