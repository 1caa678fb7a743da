#pragma once
// Elements → what a G-code controller can cut: lines (G01) and circular arcs (G02/G03) of at
// most 180°. Circular arcs stay arcs (split at 180° so no controller can read a near-full arc
// as a tiny one or vice versa); arcs too small to matter become lines; elliptical arcs (from a
// width factor or italic shear) become biarcs — pairs of tangent-continuous circular arcs —
// within a tolerance, or chords when the user asks for G01 only.
#include <vector>

#include "fonts/element.hpp"

namespace mark {

struct ArcSplineOptions {
  double tolerance_mm = 0.005;   // how far the output may leave the exact curve
  bool ellipse_chords = false;   // G01 chords instead of biarcs for elliptical arcs
  // An arc whose chord is shorter than this, or that bows less than min_arc_sagitta_mm away
  // from its chord, is cut as a line: controllers misread near-zero arcs (grbl#496).
  double min_arc_chord_mm = 0.01;
  double min_arc_sagitta_mm = 0.001;
};

// Lines and circular arcs (|sweep| ≤ π) from the element's start to its end.
std::vector<Element> arc_spline(const Element& element, const ArcSplineOptions& options);

}  // namespace mark
