#pragma once
// Preview of a CNC toolpath as SVG or PNG (by the file's extension): what the tool removes
// (engraved grooves one tool wide, the cleared pocket, or a V-carve as wide as the cone at the
// surface, shaded by depth: darker is deeper), raised letters, material the tool cannot reach in
// red, the tool-centre path solid, rapid moves dashed.
#include <string>

#include "marker/cnc/protrusion.hpp"
#include "marker/cnc/toolpath.hpp"
#include "marker/cnc/vcarve.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

// `protrusion` and `vcarve` are null unless the toolpath is theirs; a V-carve also shows its
// flat bottoms (what the end mill clears). Throws InputError naming the file when it cannot be
// written or its extension is not .svg/.png.
void write_toolpath_preview(const Figure& figure, const Toolpath& toolpath, double tool_diameter_mm,
                            const ProtrusionResult* protrusion, const std::string& path,
                            const VCarveResult* vcarve = nullptr);

}  // namespace mark
