#pragma once
// Contour passes: loops along the outline of the filled area, the first at the contour inset
// (a beam radius inside, so the mark's edge falls on the outline), each further one a contour
// spacing deeper. Loops are Clipper offsets re-fitted to exact lines and arcs (arc_refit.hpp),
// visited nearest first, each entered at its vertex nearest to the beam.
#include <vector>

#include "fonts/element.hpp"
#include "marker/fill/fill_options.hpp"
#include "marker/fill/fill_region.hpp"

namespace mark {

// The loops in drawing order; `at` is where the beam is before and is left where it ends.
std::vector<std::vector<Element>> contour_loops(const FillRegion& region, const FillOptions& options,
                                                Point& at);

}  // namespace mark
