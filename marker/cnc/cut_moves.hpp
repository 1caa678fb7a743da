#pragma once
// Elements → feed moves at a fixed depth, through the arc spline: what both generators use to
// turn geometry into ToolMoves.
#include <vector>

#include "marker/cnc/cut_settings.hpp"
#include "marker/cnc/toolpath.hpp"

namespace mark {

// Lines and circular arcs (already arc-splined) → G01/G02/G03 moves at height z.
void append_cut(const std::vector<Element>& path, double z_mm, double feed_mm_min,
                std::vector<ToolMove>& out);

// Any elements → lines and arcs within the settings' arc tolerance, in order.
std::vector<Element> machinable(const std::vector<Element>& elements, const ArcSplineOptions& arcs);

}  // namespace mark
