// The built-in marking font: our own single-stroke design (lines, circular and elliptical arcs)
// on a grid with cap height 10, x-height 7, descender −3, parsed from its glyph scripts once, at
// first use.
#include "fonts/builtin/builtin_glyphs.hpp"
#include "fonts/builtin/glyph_script.hpp"
#include "fonts/catalog.hpp"

namespace mark {
namespace {

FontMetrics builtin_metrics() {
  FontMetrics m;
  m.cap_height = 10;
  m.x_height = 7;
  m.ascender = 10;  // ascenders of b, d, f, h, k, l stand as tall as the capitals (ISO 3098)
  m.descender = -3;
  m.baseline = 0;
  m.standard_height = m.cap_height;
  m.line_height = 16;
  m.letter_spacing = 0;  // the advances carry the side bearings
  m.word_spacing = 5;
  return m;
}

StrokeFont make_builtin_font() {
  StrokeFont font(kBuiltinFontName, "built-in", builtin_metrics());
  for (const GlyphScript& g : builtin_glyph_scripts())
    font.add(parse_glyph_script(g.code_point, g.advance, g.script));
  font.set_replacement(U'?');
  return font;
}

}  // namespace

const StrokeFont& builtin_font() {
  static const StrokeFont font = make_builtin_font();
  return font;
}

}  // namespace mark
