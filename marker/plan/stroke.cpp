#include "marker/plan/stroke.hpp"

#include <algorithm>

#include "fonts/stroke_join.hpp"

namespace mark {

double Stroke::length_mm() const {
  double len = 0;
  for (const Element& e : elements) len += e.length();
  return len;
}

Stroke Stroke::reversed() const {
  Stroke r;
  r.glyph = glyph;
  r.join_tol_mm = join_tol_mm;
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
  // The same joins as every other stage (fonts/stroke_join.hpp): pieces that meet within the
  // shared fraction of the letter height are one stroke, drawn without a jump.
  const double tol = figure.join_tolerance_mm();
  for (ChainedStroke& c : chain_strokes(figure.glyphs[g].elements, tol)) {
    const Element& first = c.elements.front();
    if (c.elements.size() == 1 && first.kind() == ElementKind::line &&
        (first.end() - first.start()).norm() <= kJoinTolerance_mm)
      continue;  // a zero-length line marks nothing and has no direction
    strokes.push_back(Stroke{std::move(c.elements), g, tol});
  }
}

}  // namespace mark
