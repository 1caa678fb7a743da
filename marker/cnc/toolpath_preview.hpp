#pragma once
// Preview of a CNC toolpath as SVG or PNG (by the file's extension): what the tool removes
// (engraved grooves one tool wide, the cleared pocket, or a V-carve as wide as the cone at the
// surface, shaded by depth: darker is deeper), raised letters, material the tool cannot reach in
// red, the tool-centre path solid, rapid moves dashed.
#include <string>

#include "marker/cnc/protrusion.hpp"
#include "marker/cnc/toolpath.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

// `protrusion` is null for a depression or V-carve toolpath; `v_half_angle_rad` > 0 marks a
// V-carve (half the bit angle). Throws InputError naming the file when it cannot be written or
// its extension is not .svg/.png.
void write_toolpath_preview(const Figure& figure, const Toolpath& toolpath, double tool_diameter_mm,
                            const ProtrusionResult* protrusion, const std::string& path,
                            double v_half_angle_rad = 0);

}  // namespace mark
