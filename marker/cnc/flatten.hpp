#pragma once
// Elements → polylines, for the places that need polygons (Clipper offsets for protrusion
// pockets, previews, geometric checks) and for the 5° chord comparison with F-Engrave. The
// G-code itself keeps arcs as arcs (see arc_spline.hpp).
#include <vector>

#include "fonts/element.hpp"

namespace mark {

// Points along the element from its start to its end (both included) such that no chord leaves
// the exact curve by more than chord_tol_mm.
std::vector<Point> flatten_element(const Element& element, double chord_tol_mm);

// F-Engrave's approach: arcs (circular and elliptical) split into chords of at most `step_rad`
// of their angle parameter (F-Engrave: 5°). Lines stay single segments.
std::vector<Point> chord_element(const Element& element, double step_rad);

}  // namespace mark
