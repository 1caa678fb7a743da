#pragma once
// Glyphs a font makes when a text first asks for them, instead of holding them all from the
// start: an outline font fits a glyph's Béziers to arcs only for the characters a job marks (a
// real font has thousands of glyphs; a hostile one can point 65 000 code points at one huge
// glyph). A StrokeFont consults its source for every code point it does not hold itself.
#include <cstddef>
#include <vector>

#include "fonts/glyph.hpp"

namespace mark {

class GlyphSource {
 public:
  virtual ~GlyphSource() = default;
  // The glyph for `code_point`, made on first use and kept for the source's lifetime; nullptr
  // when the font maps no glyph to it. Throws FontFileError (naming the file, the character and
  // the limit) for a glyph that is malformed or over a limit. Safe to call from several threads.
  virtual const Glyph* find(char32_t code_point) const = 0;
  // How many code points the font maps, and which (ascending): read from the character map
  // alone, no glyph is made.
  virtual std::size_t code_point_count() const = 0;
  virtual std::vector<char32_t> code_points() const = 0;
};

}  // namespace mark
