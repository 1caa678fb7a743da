#pragma once
// A Figure: the text after layout — every glyph's elements placed in the field frame, in
// millimetres (origin at the field centre, x right, y up), with laser flags. Arcs stay arcs (or
// exact elliptical arcs where width factor or shear made them so). This is what the planner, the
// CNC writer, the dot-peen planner and the previews consume.
#include <cstddef>
#include <vector>

#include "fonts/element.hpp"

namespace mark {

// One distinct character as every occurrence of it looks before rotation and translation:
// scaled to the requested height, width factor applied, sheared (italic), mirrored. Glyph origin
// at (0, 0) on the baseline; millimetres.
struct ShapedGlyph {
  char32_t code_point = 0;
  std::vector<Element> elements;
  double advance_mm = 0;
  Affine from_font = Affine::Identity();  // font units → these local millimetres
};

// One occurrence of a character in the field.
struct PlacedGlyph {
  char32_t code_point = 0;
  std::size_t shape = 0;      // index into Figure::shapes
  std::size_t line = 0;       // text line it belongs to
  Point origin{0, 0};         // where the shaped glyph's origin lands, mm
  double rotation_rad = 0;    // rotation of the shaped glyph about its origin
  std::vector<Element> elements;  // field frame, mm; laser-off elements are pen moves

  // Shaped-glyph millimetres → field millimetres: T(origin)·R(rotation).
  Affine placement() const;
};

struct Figure {
  std::vector<ShapedGlyph> shapes;
  std::vector<PlacedGlyph> glyphs;
  // The requested character (cap) height, mm; 0 in figures not made by the layout.
  double letter_height_mm = 0;

  // Within this distance two element ends are one point (fonts/stroke_join.hpp): the shared
  // fraction of the letter height, or of the drawing's height in a figure without one.
  double join_tolerance_mm() const;

  // Bounds of all lit elements, mm.
  Box bounds() const;
  std::size_t element_count() const;
  // Total length of lit elements, mm.
  double mark_length_mm() const;
};

}  // namespace mark
