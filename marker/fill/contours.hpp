#pragma once
// Closed contours: what a fill takes. An outline-font glyph after layout is a list of lit
// elements, one closed loop after another (laser-off moves between them, or none where the next
// loop starts where the last one closed); a rectangle or a code's module is one loop.
#include <span>
#include <string_view>
#include <vector>

#include "fonts/element.hpp"

namespace mark {

struct Contour {
  std::vector<Element> elements;  // lit, each starting where the previous one ends, last ends on the first's start
};

// The lit elements cut into closed loops: a loop ends where the path comes back to where it
// began. Zero-length lines are dropped. Throws InputError naming `what` when a lit run ends
// away from its start (an open stroke — a single-line font cannot be filled).
std::vector<Contour> closed_contours(std::span<const Element> elements, std::string_view what);

// The rectangle as one counter-clockwise loop of four lines.
Contour rectangle_contour(const Box& box);

}  // namespace mark
