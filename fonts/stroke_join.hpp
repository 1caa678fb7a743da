#pragma once
// Where strokes meet: the one rule every stage uses to decide that an element's end and another
// element's start are the same point, and the one chaining of lit elements into strokes built on
// it (font loaders, the laser planner's strokes, the CNC cutting strokes, dot-peen strokes).
//
// Why relative: fonts give arc ends by centre, radius and angles, so ends that the designer meant
// to meet miss by what the file's digits can say — in QCAD's normal.cxf by up to 2.45e-4 font
// units, 2.7e-5 of the cap height (its '0', 's', '?', 'y'). An absolute tolerance joins them at
// one letter height and not at another (1e-6 mm joined nothing at 1 mm, and the cutter lifted
// and re-plunged at the same spot 9 times a row); a fraction of the letter height joins the
// same points at every height. 1e-4 of the height keeps a margin of 3.7 over the largest miss
// measured and is 0.1 µm at 1 mm, 1 µm at 10 mm: far below any tool, beam or needle, so a join
// never moves a cut visibly off the strokes (the cut crosses the gap in a straight line).
#include <vector>

#include "fonts/element.hpp"

namespace mark {

inline constexpr double kJoinFraction = 1e-4;

// The join tolerance for letters `letter_height` high (any unit: font units in a loader, mm after
// layout).
inline double join_tolerance(double letter_height) { return kJoinFraction * letter_height; }

inline bool ends_meet(const Point& a, const Point& b, double tolerance) {
  return (a - b).squaredNorm() <= tolerance * tolerance;
}

// A stroke: lit elements, each starting where the previous one ends (within the tolerance).
struct ChainedStroke {
  std::vector<Element> elements;
  Point start() const { return elements.front().start(); }
  Point end() const { return elements.back().end(); }
  bool closed(double tolerance) const { return ends_meet(start(), end(), tolerance); }
  ChainedStroke reversed() const;
};

// The lit elements of `elements` chained into strokes. A laser-off element ends a stroke. A lit
// line no longer than the tolerance is a point: dropped where a stroke passes it (a repeated
// point has no direction), else kept as a stroke of its own (a dot to strike or drill). Consecutive
// elements whose ends meet form one stroke; then strokes whose ends meet are joined end to end —
// across the element order and reversing one where needed — until no two open strokes share an
// end, so a letter drawn in pieces is cut or marked without a stop where its pieces meet.
// Geometry is never moved: a join is a decision that two ends are one point.
std::vector<ChainedStroke> chain_strokes(const std::vector<Element>& elements, double tolerance);

}  // namespace mark
