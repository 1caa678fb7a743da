#pragma once
// Contour-parallel pocketing of a tool-centre region: loops offset inward from its boundary at a
// step-over until nothing is left. Every point of the region lies within one step-over of some
// loop (the loops are the boundaries of the region eroded by k·step-over), so a step-over no
// larger than the tool radius leaves nothing uncut that the tool can reach. Each island is
// cleared from the inside out and its boundary loops — the walls — are cut last.
#include <polyclipping/clipper.hpp>

#include <vector>

#include "base/progress.hpp"
#include "fonts/box.hpp"
#include "marker/cnc/toolpath.hpp"

namespace mark {

struct PocketLoop {
  std::vector<Point> points;  // closed: the last point connects back to the first (field mm)
  int level = 0;              // 0: on the region's boundary; k: k step-overs inside
};

// The loops in cutting order (inside out per island, each island's children before it).
std::vector<PocketLoop> pocket_loops(const ClipperLib::Paths& region, double stepover_mm,
                                     double arc_tol_mm, const Progress& progress = Progress::none());

struct PocketMoves {
  double safe_z_mm = 5;
  double feed_mm_min = 300;
  double plunge_feed_mm_min = 100;
  // Links between loops longer than this go up and over instead of cutting through at depth
  // (a long link would slot through material the loops have not cleared yet).
  double max_link_mm = 1;
};

// Cuts every loop at height z, starting each at the vertex nearest to where the tool is; a
// link no longer than max_link_mm that stays inside `region` is cut at depth, any other goes up
// to safe height.
// `at` is where the tool is (updated); `at_depth` whether it is down at z already.
void append_pocket_pass(const std::vector<PocketLoop>& loops, const ClipperLib::Paths& region,
                        double z_mm, const PocketMoves& m, Point& at, bool& at_depth,
                        std::vector<ToolMove>& out, const Progress& progress = Progress::none());

}  // namespace mark
