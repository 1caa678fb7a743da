#pragma once
// Stroke assembly shared by the loaders: the pieces of a glyph become strokes (runs of lit
// elements, end to start), with laser-off line elements where the pen must move between them.
#include <vector>

#include "fonts/loaders/raw_glyph.hpp"

namespace mark::loaders {

// Pieces are taken in file order. A piece joins the stroke being built when one of its ends lies
// within `tolerance` of one of the stroke's ends: it is appended (reversed if it meets the stroke's
// end with its own end), or prepended when it ends where the stroke starts; when it starts where
// the stroke starts, the stroke is reversed and the piece appended. Geometry never changes, only
// the direction of travel, and no laser-off move is left between pieces that touch. Elements no
// longer than `tolerance` (repeated points) are dropped.
std::vector<Element> assemble_strokes(const RawGlyph& glyph, double tolerance);

// The same, keeping its working buffers from one glyph to the next (a font has thousands).
class StrokeAssembler {
 public:
  explicit StrokeAssembler(double tolerance) : tolerance_(tolerance) {}
  std::vector<Element> assemble(const RawGlyph& glyph);

 private:
  double tolerance_;
  std::vector<Element> lit_;
  std::vector<std::size_t> stroke_begin_;
};

}  // namespace mark::loaders
