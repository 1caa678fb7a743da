#include "marker/plan/stroke.hpp"

#include <algorithm>

namespace mark {

double Stroke::length_mm() const {
  double len = 0;
  for (const Element& e : elements) len += e.length();
  return len;
}

Stroke Stroke::reversed() const {
  Stroke r;
  r.glyph = glyph;
  r.elements.reserve(elements.size());
  for (auto it = elements.rbegin(); it != elements.rend(); ++it) r.elements.push_back(it->reversed());
  return r;
}

std::vector<Stroke> strokes_of(const Figure& figure) {
  std::vector<Stroke> strokes;
  for (std::size_t g = 0; g < figure.glyphs.size(); ++g) append_glyph_strokes(figure, g, strokes);
  return strokes;
}

void append_glyph_strokes(const Figure& figure, std::size_t g, std::vector<Stroke>& strokes) {
  {
    Stroke current;
    current.glyph = g;
    auto flush = [&] {
      if (!current.elements.empty()) strokes.push_back(std::move(current));
      current = Stroke{};
      current.glyph = g;
    };
    for (const Element& e : figure.glyphs[g].elements) {
      if (!e.laser()) {
        flush();
        continue;
      }
      if ((e.end() - e.start()).norm() <= kJoinTolerance_mm && e.kind() == ElementKind::line)
        continue;  // a zero-length line marks nothing and has no direction
      if (!current.elements.empty() &&
          (current.elements.back().end() - e.start()).norm() > kJoinTolerance_mm)
        flush();
      current.elements.push_back(e);
    }
    flush();
  }
}

}  // namespace mark
