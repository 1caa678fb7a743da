#pragma once
// The bridge to Clipper 1 (Debian libpolyclipping): millimetres ↔ integer nanometres, strokes as
// open polylines, and the few region queries the pocketing needs. Clipper works on integers,
// and its round joins take their step count from the offset in those units, so everything is
// scaled to 1 unit = 1 nm first.
#include <polyclipping/clipper.hpp>

#include <vector>

#include "fonts/element.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

// Tolerances of the stroke outlines handed to Clipper: strokes flattened within kChordTolMm, round
// joins within kArcTolMm (the CNC protrusion check and the letter contacts use the same).
inline constexpr double kChordTolMm = 0.001;
inline constexpr double kArcTolMm = 0.002;

inline constexpr double kNmPerMm = 1e6;

ClipperLib::IntPoint to_nm(const Point& p);
Point to_mm(const ClipperLib::IntPoint& p);
std::vector<Point> to_mm(const ClipperLib::Path& path);

// Every lit stroke of the Figure (field frame) as an open polyline, flattened within chord_tol_mm.
ClipperLib::Paths stroke_polylines(const Figure& figure, double chord_tol_mm);
// The same for one placed glyph, appended to `out`.
void append_glyph_polylines(const PlacedGlyph& glyph, double chord_tol_mm, ClipperLib::Paths& out);

// Strokes grown by `radius_mm` with round ends and joins (the region a round tool or a stroke
// of width 2·radius covers), as a union of closed polygons.
ClipperLib::Paths grow_strokes(const ClipperLib::Paths& strokes, double radius_mm,
                               double arc_tol_mm);

// A closed loop of elements (ending where it starts) flattened within chord_tol_mm, as one
// polygon without repeated points (fewer than 3 points: a loop that encloses nothing).
ClipperLib::Path loop_polygon(const std::vector<Element>& loop, double chord_tol_mm);

// The union of closed polygons under the non-zero (TrueType, CFF) or even-odd rule: strictly
// simple polygons, outer boundaries counter-clockwise (positive area), holes clockwise.
ClipperLib::Paths union_polygons(const ClipperLib::Paths& polygons, bool even_odd);

// Closed polygons offset by delta_mm (negative shrinks), round joins.
ClipperLib::Paths offset_region(const ClipperLib::Paths& region, double delta_mm, double arc_tol_mm);

ClipperLib::Paths difference(const ClipperLib::Paths& a, const ClipperLib::Paths& b);
ClipperLib::Paths intersection(const ClipperLib::Paths& a, const ClipperLib::Paths& b);

// Total area (outer boundaries positive, holes negative), mm².
double area_mm2(const ClipperLib::Paths& region);
// Inside the region under the even-odd rule (boundary counts as inside).
bool contains(const ClipperLib::Paths& region, const Point& p);

// Does the segment ab stay inside the region (midpoint inside, no boundary edge crossed)?
bool segment_inside(const ClipperLib::Paths& region, const Point& a, const Point& b);

ClipperLib::Path rectangle_nm(const Box& box);

}  // namespace mark
