#pragma once
// A glyph of the stroke database: its elements in stroke order, in the font's own units, with
// the baseline at y = 0, y up, and the glyph origin at x = 0. Elements with the laser off are the
// pen moves between strokes inside the glyph.
#include <vector>

#include "fonts/element.hpp"

namespace mark {

struct Glyph {
  char32_t code_point = 0;
  std::vector<Element> elements;
  double advance = 0;  // from this glyph's origin to the next glyph's origin, font units

  // Bounds of the lit elements (empty for a space).
  Box bounds() const {
    Box b;
    for (const Element& e : elements)
      if (e.laser()) b.add(e.bounds());
    return b;
  }
};

}  // namespace mark
