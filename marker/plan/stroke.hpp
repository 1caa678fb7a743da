#pragma once
// A stroke: a maximal run of lit elements that follow each other without a gap — what the laser
// draws in one go. The planner orders strokes, may reverse them, and decides their corners.
#include <cstddef>
#include <vector>

#include "fonts/element.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

// Command ends closer than this (mm) need no jump between them: rounding, not a gap. Whether two
// strokes' ends are one point is the shared join rule's decision (fonts/stroke_join.hpp).
inline constexpr double kJoinTolerance_mm = 1e-6;

struct Stroke {
  std::vector<Element> elements;  // all lit, each starting where the previous one ends
  std::size_t glyph = 0;          // index of the placed glyph it comes from
  double join_tol_mm = kJoinTolerance_mm;  // ends this close are one point (the figure's join tolerance)

  Point start() const { return elements.front().start(); }
  Point end() const { return elements.back().end(); }
  bool closed() const { return (start() - end()).norm() <= join_tol_mm; }
  double length_mm() const;
  // The same path drawn the other way round.
  Stroke reversed() const;
};

// The strokes of a figure in glyph order, each glyph's lit elements chained into strokes by the
// shared join rule (fonts/stroke_join.hpp: pieces that meet within a fraction of the letter
// height, also across the font's drawing order). Laser-off elements (pen moves inside a glyph)
// and zero-length lines are dropped: the planner makes its own jumps.
std::vector<Stroke> strokes_of(const Figure& figure);
// The strokes of glyph `g` alone, appended to `strokes`.
void append_glyph_strokes(const Figure& figure, std::size_t g, std::vector<Stroke>& strokes);

}  // namespace mark
