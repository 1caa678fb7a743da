#pragma once
// Clipper works on polygons, so a loop that comes out of it (a union's boundary, an inset
// contour) is a chain of short chords even where the outline was a line or an arc. This puts the
// exact geometry back: each polygon vertex is matched to the source elements (and, for an inset,
// their corner points, which grow the round joins) it lies at the inset distance from; a run of
// vertices on one source becomes one line, or one arc concentric with the source arc (radius
// changed by the inset), or one round-join arc about a corner. Vertices that match nothing stay
// chords. The loop stays closed: every element starts where the previous one ended, exactly.
#include <vector>

#include "fonts/element.hpp"

namespace mark {

struct RefitOptions {
  double distance_mm = 0;   // how far inside the sources the loop lies (the inset)
  double tolerance_mm = 0.002;  // how far off that distance a vertex may be and still match
};

// `loop` is closed (its last point connects back to its first), at least 3 points.
std::vector<Element> refit_loop(const std::vector<Point>& loop, const std::vector<Element>& sources,
                                const RefitOptions& options);

}  // namespace mark
