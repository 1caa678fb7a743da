#pragma once
// Strokes: maximal runs of connected lit elements, the unit the cutter follows without lifting.
// Runs that meet end to end (also across the font's stroke order, or reversed) are joined, so a
// letter like "O" drawn in two halves becomes one closed stroke.
#include <vector>

#include "fonts/element.hpp"

namespace mark {

struct Stroke {
  std::vector<Element> elements;  // each starts where the previous one ends
  Point start() const { return elements.front().start(); }
  Point end() const { return elements.back().end(); }
  bool closed(double tol_mm = 1e-6) const { return (start() - end()).norm() <= tol_mm; }
  Stroke reversed() const;
};

// The lit elements of `elements` (laser-off ones are pen moves and separate strokes) chained
// into strokes; endpoints closer than join_tol_mm count as the same point.
std::vector<Stroke> chain_strokes(const std::vector<Element>& elements, double join_tol_mm = 1e-6);

}  // namespace mark
