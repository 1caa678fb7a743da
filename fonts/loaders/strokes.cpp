#include "fonts/loaders/strokes.hpp"

#include <algorithm>

namespace mark::loaders {
namespace {

// Reverses the run [first, last) of elements in place: order and direction of each.
void reverse_run(std::vector<Element>::iterator first, std::vector<Element>::iterator last) {
  std::reverse(first, last);
  for (auto it = first; it != last; ++it) *it = it->reversed();
}

}  // namespace

std::vector<Element> assemble_strokes(const RawGlyph& glyph, double tolerance) {
  return StrokeAssembler(tolerance).assemble(glyph);
}

std::vector<Element> StrokeAssembler::assemble(const RawGlyph& glyph) {
  const double tolerance = tolerance_;
  const double tol2 = tolerance * tolerance;
  const auto near = [tol2](const Point& a, const Point& b) {
    return (a - b).squaredNorm() <= tol2;
  };

  // All strokes back to back; stroke k is lit[stroke_begin[k] .. stroke_begin[k+1]). Only the
  // last stroke ever changes, so it is always the tail of `lit`.
  std::vector<Element>& lit = lit_;
  lit.clear();
  std::vector<std::size_t>& stroke_begin = stroke_begin_;
  stroke_begin.clear();
  std::size_t begin = 0;
  for (std::size_t end : glyph.piece_ends) {
    const std::size_t piece_begin = lit.size();
    for (std::size_t i = begin; i < end; ++i)
      if (glyph.elements[i].length() > tolerance) lit.push_back(glyph.elements[i]);
    begin = end;
    if (lit.size() == piece_begin) continue;
    const auto piece = lit.begin() + static_cast<std::ptrdiff_t>(piece_begin);
    if (stroke_begin.empty()) {
      stroke_begin.push_back(piece_begin);
      continue;
    }
    const auto stroke = lit.begin() + static_cast<std::ptrdiff_t>(stroke_begin.back());
    const Point p0 = piece->start(), p1 = lit.back().end();
    const Point s0 = stroke->start(), s1 = (piece - 1)->end();
    if (near(p0, s1)) continue;  // already in place after the stroke
    if (near(p1, s0)) {          // goes before the stroke
      std::rotate(stroke, piece, lit.end());
    } else if (near(p1, s1)) {  // appended backwards
      reverse_run(piece, lit.end());
    } else if (near(p0, s0)) {  // the stroke backwards, then the piece
      reverse_run(stroke, piece);
    } else {
      stroke_begin.push_back(piece_begin);
    }
  }

  std::vector<Element> out;
  out.reserve(lit.size() + stroke_begin.size());
  for (std::size_t k = 0; k < stroke_begin.size(); ++k) {
    const auto first = lit.begin() + static_cast<std::ptrdiff_t>(stroke_begin[k]);
    const auto last = k + 1 < stroke_begin.size()
                          ? lit.begin() + static_cast<std::ptrdiff_t>(stroke_begin[k + 1])
                          : lit.end();
    // A stroke that grew at its start may now begin where the one before it ends: no move then.
    if (!out.empty() && !near(out.back().end(), first->start()))
      out.push_back(Element::line(out.back().end(), first->start(), false));
    out.insert(out.end(), first, last);
  }
  return out;
}

}  // namespace mark::loaders
