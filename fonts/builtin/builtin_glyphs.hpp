#pragma once
// The built-in marking font's glyphs as drawing scripts (see glyph_script.hpp), one line each.
#include <span>

namespace mark {

struct GlyphScript {
  char32_t code_point;
  double advance;      // font units; the design grid has cap height 10, x-height 7
  const char* script;  // empty for the space
};

std::span<const GlyphScript> builtin_glyph_scripts();

}  // namespace mark
