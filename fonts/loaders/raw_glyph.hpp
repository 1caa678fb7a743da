#pragma once
// A glyph as a loader reads it, before stroke assembly: the lit elements in file order, grouped
// into pieces the file draws without lifting the pen (a Hershey pen-down run, an LFF polyline, a
// CXF record).
#include <cstddef>
#include <vector>

#include "fonts/element.hpp"

namespace mark::loaders {

struct RawGlyph {
  char32_t code_point = 0;
  std::size_t line = 0;  // where the glyph starts in the file, for messages
  double advance = 0;
  std::vector<Element> elements;
  // elements[piece_ends[k-1] .. piece_ends[k]) is piece k (from 0 for k = 0).
  std::vector<std::size_t> piece_ends;

  // Closes the piece being added to (no-op when it is empty).
  void end_piece() {
    const std::size_t begin = piece_ends.empty() ? 0 : piece_ends.back();
    if (elements.size() > begin) piece_ends.push_back(elements.size());
  }
  // Appends all of `other`'s pieces after this glyph's (an LFF glyph reference).
  void append_pieces(const RawGlyph& other) {
    end_piece();
    const std::size_t offset = elements.size();
    elements.insert(elements.end(), other.elements.begin(), other.elements.end());
    for (std::size_t end : other.piece_ends) piece_ends.push_back(offset + end);
  }
  Box bounds() const {
    Box b;
    for (const Element& e : elements) b.add(e.bounds());
    return b;
  }
};

}  // namespace mark::loaders
