#pragma once
// The narrowest gap between strokes: where a tool at least that wide cuts two neighbouring
// grooves into one (a 1 mm tool on 1 mm text, a 50 mm tool on 5 mm text gave one solid groove
// without a word).
//
// A gap is a pair of points on the strokes (different strokes, different letters, or two parts
// of one stroke such as the sides of an 'O'), farther apart than the join tolerance, that face
// each other: at each point the line to the other is square to the stroke (within 30°), or the
// point is a free end of a stroke (the tip of an 'i' stem under its dot). Strokes that meet or
// cross are not a gap, nor are the two arms of a 'V' near its apex (they touch).
#include <optional>

#include "base/progress.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

struct StrokeGap {
  double width_mm = 0;  // distance between the two facing points
  Point a{0, 0}, b{0, 0};  // the points, field frame
};

// The narrowest gap no wider than `up_to_mm`, or nothing if every gap is wider. Strokes are
// flattened to 1e-3 of the letter height for the search; the width is exact to that.
std::optional<StrokeGap> narrowest_stroke_gap(const Figure& figure, double up_to_mm,
                                              const Progress& progress = Progress::none());

}  // namespace mark
