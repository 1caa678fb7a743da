#pragma once
// The narrowest gap between strokes: where a tool at least that wide cuts two neighbouring
// grooves into one (a 1 mm tool on 1 mm text, a 50 mm tool on 5 mm text gave one solid groove
// without a word).
//
// A gap is a pair of points on the strokes (different strokes, different letters, or two parts
// of one stroke such as the sides of an 'O') that face each other: the line between them is
// square to both strokes (within 5°), or ends in a corner within its normal cone, or in a free
// end that it leaves inwards-away (the tip of an 'i' stem under its dot). Strokes that meet or
// cross are not a gap, nor is the wedge where two strokes touch tangentially or the arms of a
// 'V' near its apex, nor are points closer than 0.5 % of the letter height (a T-junction that
// misses its crossbar by a rounding).
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
