#pragma once
// Raised letters that run into each other. A protrusion letter is its strokes grown by half the
// stroke width; when two letters' regions overlap, the engraving leaves them joined — one lump
// of material where the reader expects two letters. Found before any toolpath is cut so the
// command can say which letters and what to change.
#include <cstddef>
#include <vector>

#include "marker/layout/figure.hpp"

namespace mark {

struct LetterContact {
  std::size_t first = 0;   // glyph indices in the Figure, first < second
  std::size_t second = 0;
  double area_mm2 = 0;     // area the two raised letters share
  Point at{0, 0};          // centre of the shared area's bounds, field frame
};

// Every pair of glyphs whose strokes, grown to `stroke_width_mm`, overlap by more than 1 µm².
std::vector<LetterContact> touching_letters(const Figure& figure, double stroke_width_mm);

}  // namespace mark
