#pragma once
// V-carving: letters with closed outlines (outline fonts through FreeType, closed contours of
// any font) cut with a V-bit whose tip follows each letter's medial axis (medial_axis.hpp) at
// depth = distance to the outline / tan(half the bit angle), so the cone's rim at the surface
// runs along the outline: sharp inside corners, walls at the bit's angle.
//
// The depth is capped at --max-depth and at what the bit's diameter can cut (radius at the
// surface ≤ the bit's radius). Where the cap flattens the carve, the letter has a flat bottom:
// the V-bit goes once round its edge at full depth (cutting the walls beside it), and a
// flat-bottom end mill, if given, clears it in a second program (a tool change, as F-Engrave
// writes its clean-up): contour-parallel loops of the flat region eroded by the mill's radius.
//
// Tolerances: the outline is flattened within half the tolerance and the axis is sampled and
// pruned within it; where curves were flattened the polygon can stand up to that far outside a
// concave curve of the true outline, so every radius is reduced by it (and by the sampling
// tolerance on curved axis edges): the cone never crosses the true outline, and its depth is
// within tolerance / tan(half angle) of the exact medial-axis depth.
#include <polyclipping/clipper.hpp>

#include <vector>

#include "base/progress.hpp"
#include "marker/cnc/cut_settings.hpp"
#include "marker/cnc/medial_axis.hpp"
#include "marker/cnc/toolpath.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

struct VCarveSettings {
  double bit_angle_deg = 60;      // included angle of the V-bit
  double max_depth_mm = 0;        // 0: only the bit's diameter limits the depth
  double flat_bottom_mm = 0;      // diameter of the clean-up end mill; 0: no clean-up program
  double stepover_mm = 0;         // clean-up loops; 0: 40 % of the end mill's diameter
  double tolerance_mm = 0.002;    // outline flattening (half of it) and axis sampling
  bool even_odd = false;          // inside of overlapping contours: non-zero (TrueType, CFF) or even-odd
};

struct VCarveLetter {
  ClipperLib::Paths region;       // the letter's area in its own mm, as nm polygons
  MedialAxis axis;                // its medial axis, letter mm
  ClipperLib::Paths flat;         // where the depth cap leaves a flat bottom (nm, letter mm)
  double margin_mm = 0;           // how much every radius was reduced (see above)
};

struct VCarveResult {
  Toolpath toolpath;              // the V-bit program
  Toolpath cleanup;               // the end-mill program (empty without flat_bottom_mm)
  std::vector<VCarveLetter> letters;  // per distinct character (Figure::shapes index → letters[sub])
  double depth_limit_mm = 0;      // the cap in force: min(--max-depth, what the bit's diameter can cut)
  double deepest_mm = 0;          // the deepest cut of the carve (≤ the cap)
  double flat_area_mm2 = 0;       // flat bottoms, every occurrence counted
  double uncleaned_area_mm2 = 0;  // of that, what the end mill cannot reach (corners), or all of it without one
  std::size_t axis_edges = 0;     // Voronoi edges inside the letters, before pruning (distinct letters)
  std::size_t pruned_edges = 0;   // of those, pruned as adding nothing beyond the tolerance
  double half_angle_rad = 0;      // half the bit angle
};

// Throws InputError for an open stroke (naming the character), impossible settings, or a text
// without letters; Interrupted when `progress` says stop. `cut` gives the V-bit's diameter,
// feeds, safe height and depth per pass (0: full depth in one pass).
VCarveResult vcarve_toolpath(const Figure& figure, const CutSettings& cut, const VCarveSettings& settings,
                             const Progress& progress = Progress::none());

}  // namespace mark
