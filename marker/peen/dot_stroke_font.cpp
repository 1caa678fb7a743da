#include "marker/peen/dot_stroke_font.hpp"

namespace mark {

StrokeFont as_stroke_font(const DotFont& font) {
  const double cols = font.columns(), rows = font.rows();
  FontMetrics m;
  m.cap_height = rows - 1;
  m.x_height = rows - 1;
  m.ascender = rows - 1;
  m.descender = 0;
  m.baseline = 0;
  m.standard_height = rows - 1;
  m.line_height = rows + 2;  // two empty rows between lines
  m.letter_spacing = 0;
  m.word_spacing = cols + 1;
  StrokeFont out(font.name(), "built-in dot matrix " + font.name(), m);
  for (const auto& [cp, dot_glyph] : font.glyphs()) {
    Glyph g;
    g.code_point = cp;
    g.advance = cols + 1;
    for (const DotCell& d : dot_glyph.dots) {
      const Point p(d.col, rows - 1 - d.row);
      g.elements.push_back(Element::line(p, p, true));
    }
    out.add(std::move(g));
  }
  return out;
}

}  // namespace mark
