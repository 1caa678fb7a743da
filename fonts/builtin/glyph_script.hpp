#pragma once
// The little drawing language the built-in font's glyphs are written in, so that each glyph is
// one reviewable line of source instead of a list of constructor calls.
//
//   M x,y                  pen up to (x, y)
//   L x,y                  line from the pen to (x, y)
//   A cx,cy,r,a0,a1        circular arc, angles in degrees; sweep = a1 − a0 (signed, so
//                          a1 < a0 runs clockwise)
//   E cx,cy,rx,ry,a0,a1    axis-aligned elliptical arc, parametric angles in degrees
//
// Numbers are plain decimals (no exponents), separated by commas inside a group; groups are
// separated by white space, and further groups after a command repeat it ("M1,0 L4,10 7,0" is a
// two-segment polyline).
//
// Joins: an element that starts within 1e-9 of the pen continues the stroke. One that starts
// elsewhere is reached by a laser-off move, inserted automatically (so every M, and every arc
// that starts away from the pen, begins a new stroke). A line whose written end lies within 0.01
// of the start of the arc after it is snapped onto that start, so a line can run into an arc at
// an irrational point without 10-digit coordinates. The parser keeps the design honest: an arc
// that ends within 0.01 of the next element's start without joining it (a near miss that would
// mark a tiny gap), an M followed by an arc that starts 0.01 or more away from it, a zero-length
// element and a trailing M are errors.
#include <string_view>

#include "fonts/glyph.hpp"

namespace mark {

// Throws InputError naming the glyph (as `describe_code_point` does), the offending token and its
// offset in the script.
Glyph parse_glyph_script(char32_t code_point, double advance, std::string_view script);

}  // namespace mark
