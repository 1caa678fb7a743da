#pragma once
// Protrusion (raised) letters, as in the paper's protrusion font generator: the letters stand
// proud and the material around them inside a boundary rectangle is pocketed away.
//   letters   L = strokes grown by half the stroke width (default: the nominal tool diameter)
//   plate     R = bounds of L plus a margin
//   tool-centre region P = (R inset by the tool radius) − (L grown by the tool radius)
// P is cleared with contour-parallel loops at a step-over; its outermost loop runs the tool
// along the inside of R — the boundary groove, one tool wide — and round every letter. Material
// the tool cannot reach (places narrower than the tool between letters) is reported, never
// gouged. The tool radius is the measured one when a tool image was measured (tool_measure.hpp).
#include <polyclipping/clipper.hpp>

#include <vector>

#include "base/progress.hpp"
#include "marker/cnc/cut_settings.hpp"
#include "marker/cnc/toolpath.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

struct ProtrusionSettings {
  double stroke_width_mm = 0;  // width of the raised strokes; 0 = tool diameter
  // From the letters to the boundary rectangle; 0 = twice the tool diameter, so the tool fits
  // between the letters and the wall with room to spare.
  double margin_mm = 0;
  double stepover_mm = 0;      // between pocket loops; 0 = 40 % of the tool diameter
  // Cut the walls (letters and boundary) as the programmed part contour with G41/G42 and let
  // the control offset by the tool radius in its D register, instead of offsetting here.
  bool cutter_comp = false;
};

struct UncutRegion {
  double area_mm2 = 0;
  Box bounds;
};

struct ProtrusionResult {
  Toolpath toolpath;
  Box plate;                          // the boundary rectangle R
  ClipperLib::Paths letters;          // L, nm
  ClipperLib::Paths tool_region;      // P, nm: where the tool centre may go
  ClipperLib::Paths cleared;          // P grown by the tool radius: what the tool removes
  std::vector<UncutRegion> uncut;     // material inside R, outside L, the tool cannot reach
  ClipperLib::Paths uncut_region;     // the same as polygons, nm
  double stroke_width_mm = 0;
  double stepover_mm = 0;
  std::size_t loops = 0;              // pocket loops per pass
  std::size_t comp_walls = 0;         // --cutter-comp: walls programmed as part contours
  std::size_t walls_without_comp = 0; // --cutter-comp: walls without room for a lead move
};

// Throws InputError for impossible settings (step-over above the tool radius, nothing to cut).
ProtrusionResult protrusion_toolpath(const Figure& figure, const CutSettings& settings,
                                     const ProtrusionSettings& protrusion,
                                     const Progress& progress = Progress::none());

}  // namespace mark
