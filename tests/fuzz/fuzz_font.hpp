#pragma once
// What every font-loader fuzz target checks: the parser either throws InputError (a malformed
// file, reported) or returns a font that downstream code can trust — at least one glyph, finite
// metrics and geometry, lit elements of positive length, laser-off moves only between strokes,
// and a pen path without gaps. Anything else (a crash, a sanitizer report, another exception, a
// broken invariant) is a bug.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "base/error.hpp"
#include "fonts/loaders.hpp"
#include "fonts/stroke_join.hpp"

namespace mark::fuzz {

[[noreturn]] inline void broken(const char* what, char32_t cp) {
  std::fprintf(stderr, "fuzz invariant broken: %s (glyph U+%04X)\n", what,
               static_cast<unsigned>(cp));
  std::abort();
}

inline bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

// One glyph filed under `cp`: finite, lit elements of positive length, laser-off moves only
// between strokes (never first, last or two in a row), no gap in the pen path.
inline void check_glyph(const Glyph& g, char32_t cp, double gap_tol) {
  if (!std::isfinite(g.advance)) broken("non-finite advance", cp);
  const auto& els = g.elements;
  if (!els.empty() && (!els.front().laser() || !els.back().laser()))
    broken("glyph starts or ends with a laser-off move", cp);
  for (std::size_t i = 0; i < els.size(); ++i) {
    const Element& e = els[i];
    if (!finite(e.start()) || !finite(e.end()) || !std::isfinite(e.length()))
      broken("non-finite element", cp);
    const Box b = e.bounds();
    if (!finite(b.min) || !finite(b.max)) broken("non-finite bounds", cp);
    if (e.laser() && !(e.length() > 0)) broken("lit element of zero length", cp);
    if (i > 0) {
      if (!e.laser() && !els[i - 1].laser()) broken("two laser-off moves in a row", cp);
      if ((e.start() - els[i - 1].end()).norm() > gap_tol) broken("gap in the pen path", cp);
    }
  }
}

inline void check_metrics(const StrokeFont& font) {
  if (font.size() == 0) broken("a font without glyphs was returned", 0);
  const FontMetrics& m = font.metrics();
  for (double v : {m.cap_height, m.x_height, m.ascender, m.descender, m.baseline, m.standard_height,
                   m.line_height, m.letter_spacing, m.word_spacing})
    if (!std::isfinite(v)) broken("non-finite metric", 0);
  if (!(m.standard_height > 0)) broken("standard height is not positive", 0);
  if (m.ascender < 0 || m.descender > 0) broken("ascender/descender on the wrong side", 0);
}

// A font whose glyphs are all held (the stroke-font parsers).
inline void check_font(const StrokeFont& font) {
  check_metrics(font);
  Box all;
  for (const auto& [cp, g] : font.glyphs()) all.add(g.bounds());
  // The loaders join pieces whose ends lie within the join tolerance of the letter height
  // (fonts/stroke_join.hpp: the font's cap height, else its drawing's height), so the pen path
  // may step by that much and no more.
  const FontMetrics& m = font.metrics();
  const double height = std::max({m.cap_height, m.standard_height, all.height()});
  const double gap_tol = 1e-6 * std::max(1.0, std::max(all.width(), all.height())) +
                         join_tolerance(height) * (1 + 1e-9);
  for (const auto& [cp, g] : font.glyphs()) {
    if (g.code_point != cp) broken("glyph filed under another code point", cp);
    check_glyph(g, cp, gap_tol);
  }
}

// The whole fuzz target body for one parser.
template <class Parse>
int run(const std::uint8_t* data, std::size_t size, Parse parse, const char* source) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Warnings warnings;
  try {
    check_font(parse(text, source, &warnings));
  } catch (const InputError&) {
    // A reported malformed file: the expected outcome for most inputs.
  }
  for (const std::string& w : warnings)
    if (w.rfind(source, 0) != 0) broken("warning does not name the source", 0);
  return 0;
}

}  // namespace mark::fuzz
