#pragma once
// A stroke: a maximal run of lit elements that follow each other without a gap — what the laser
// draws in one go. The planner orders strokes, may reverse them, and decides their corners.
#include <cstddef>
#include <vector>

#include "fonts/element.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

// Two element ends closer than this (mm) are the same point.
inline constexpr double kJoinTolerance_mm = 1e-6;

struct Stroke {
  std::vector<Element> elements;  // all lit, each starting where the previous one ends
  std::size_t glyph = 0;          // index of the placed glyph it comes from

  Point start() const { return elements.front().start(); }
  Point end() const { return elements.back().end(); }
  bool closed() const { return (start() - end()).norm() <= kJoinTolerance_mm; }
  double length_mm() const;
  // The same path drawn the other way round.
  Stroke reversed() const;
};

// The strokes of a figure in glyph order, each glyph's strokes in its element order. Laser-off
// elements (pen moves inside a glyph) and zero-length elements are dropped: the planner makes
// its own jumps.
std::vector<Stroke> strokes_of(const Figure& figure);
// The strokes of glyph `g` alone, appended to `strokes`.
void append_glyph_strokes(const Figure& figure, std::size_t g, std::vector<Stroke>& strokes);

}  // namespace mark
