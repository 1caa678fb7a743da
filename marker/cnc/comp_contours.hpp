#pragma once
// Control-side cutter compensation for the pocket walls (--cutter-comp): instead of the
// tool-centre loop next to each wall, the program carries the wall itself — the part contour —
// and G41 makes the control keep the tool one radius (its D register) to the left. The control
// can then absorb further wear without a new program.
//
// The programmed wall is the boundary of (P ⊖ ε) ⊕ (r + ε), P the tool-centre region: offset
// back by r it gives P opened by ε, so the compensated tool never leaves P, and every corner of
// the wall is rounder than the tool (radius ≥ r + ε, ε = r/4) so the control never meets a concave corner
// it cannot reach. Each contour is entered and left by a straight lead move, longer than the
// tool radius as controls require, that lies inside P and meets the wall at a shallow angle.
#include <polyclipping/clipper.hpp>

#include <vector>

#include "fonts/box.hpp"
#include "marker/cnc/pocket.hpp"
#include "marker/cnc/toolpath.hpp"

namespace mark {

struct CompContour {
  std::vector<Point> wall;  // closed: starts and ends at the entry point, tool on the left
  Point lead{0, 0};         // where the tool centre is before G41 and after G40
};

// Walls that leave no room for a lead move (a small counter, a narrow gap) are left out and
// counted in `without_lead`: their tool-centre loops stay in the program instead.
std::vector<CompContour> comp_contours(const ClipperLib::Paths& tool_region, double tool_radius_mm,
                                       double arc_tol_mm, std::size_t& without_lead);

// Does the tool-centre loop run along the contour's wall, one tool radius off it?
bool follows_wall(const std::vector<Point>& loop, const CompContour& contour, double tool_radius_mm);

// Every contour at height z with G41 on the lead-in and G40 on the lead-out.
void append_comp_contours(const std::vector<CompContour>& contours, const ClipperLib::Paths& tool_region,
                          double z_mm, const PocketMoves& m, Point& at, bool& at_depth,
                          std::vector<ToolMove>& out);

}  // namespace mark
