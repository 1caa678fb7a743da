#pragma once
// Cutting strokes: maximal runs of connected lit elements of one character (in its own
// coordinates), the unit the cutter follows without lifting. Unlike the laser planner's strokes
// (marker/plan/stroke.hpp, per Figure), runs that meet end to end — also across the font's stroke
// order, or reversed — are joined, so a letter like "O" drawn in two halves becomes one closed
// stroke and is cut in passes without lifting.
#include <vector>

#include "fonts/element.hpp"

namespace mark {

struct CutStroke {
  std::vector<Element> elements;  // each starts where the previous one ends
  Point start() const { return elements.front().start(); }
  Point end() const { return elements.back().end(); }
  bool closed(double tol_mm = 1e-6) const { return (start() - end()).norm() <= tol_mm; }
  CutStroke reversed() const;
};

// The lit elements of `elements` (laser-off ones are pen moves and separate strokes) chained
// into strokes; endpoints closer than join_tol_mm count as the same point.
std::vector<CutStroke> chain_cut_strokes(const std::vector<Element>& elements, double join_tol_mm = 1e-6);

}  // namespace mark
