#pragma once
// Figures built by hand for the planner tests: one placed glyph per stroke list.
#include <vector>

#include "marker/layout/figure.hpp"

namespace mark::test {

inline Figure figure_of(const std::vector<std::vector<Element>>& glyphs) {
  Figure f;
  for (const auto& elements : glyphs) {
    PlacedGlyph g;
    g.code_point = U'x';
    g.elements = elements;
    f.glyphs.push_back(g);
  }
  return f;
}

}  // namespace mark::test
