#include "marker/peen/dot_layout.hpp"

#include <cmath>

#include "marker/peen/dot_stroke_font.hpp"

namespace mark {

DotText layout_dot_text(std::string_view utf8_text, const DotFont& font,
                        const LayoutOptions& options) {
  const StrokeFont as_strokes = as_stroke_font(font);
  const Figure figure = layout_text(utf8_text, as_strokes, options);
  DotText out;
  out.pitch_mm = options.height_mm / (font.rows() - 1);
  for (const PlacedGlyph& g : figure.glyphs) {
    const ShapedGlyph& shape = figure.shapes.at(g.shape);
    // Field mm → font units (dot pitches): undoes rotation, translation, scale, width factor,
    // shear and mirror at once, so each dot's cell comes back exactly.
    const Affine font_to_field = g.placement() * shape.from_font;
    const Affine to_font = font_to_field.inverse();
    const bool mirrored = shape.from_font.linear().determinant() < 0;
    // Cell (col, row) as seen → font units: rows count down from the top row; a mirrored
    // character's columns count from the font's right.
    Affine cell_to_font = Affine::Identity();
    cell_to_font.linear() << (mirrored ? -1.0 : 1.0), 0.0, 0.0, -1.0;
    cell_to_font.translation() = Point(mirrored ? font.columns() - 1 : 0, font.rows() - 1);
    bool any = false;
    for (const Element& e : g.elements) {
      if (!e.laser()) continue;
      const Point pos = e.start();
      const Point f = to_font * pos;
      int col = static_cast<int>(std::lround(f.x()));
      const int row = font.rows() - 1 - static_cast<int>(std::lround(f.y()));
      // The block snake walks the matrix as the character is seen on the part.
      if (mirrored) col = font.columns() - 1 - col;
      out.dots.push_back({pos, out.characters, {col, row}});
      any = true;
    }
    if (!any) continue;
    out.cell_frames.push_back(font_to_field * cell_to_font);
    ++out.characters;
  }
  return out;
}

}  // namespace mark
