#include "fonts/loaders/font_builder.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <unordered_map>
#include <variant>

#include "fonts/error.hpp"
#include "fonts/loaders/strokes.hpp"
#include "fonts/overloaded.hpp"

namespace mark::loaders {
namespace {

// Coincidence tolerance relative to the size of the font's drawing.
constexpr double kRelativeJoinTolerance = 1e-9;

bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

// Loader input is range-checked, so this never fires; it keeps a geometry bug from ever handing
// NaN coordinates to a scanner.
bool element_is_finite(const Element& e) {
  return std::visit(
      Overloaded{[](const Line& l) { return finite(l.start) && finite(l.end); },
                 [](const CircularArc& a) {
                   return finite(a.center) && std::isfinite(a.radius) &&
                          std::isfinite(a.start_angle) && std::isfinite(a.sweep);
                 },
                 [](const EllipticalArc& a) {
                   return finite(a.center) && std::isfinite(a.rx) && std::isfinite(a.ry) &&
                          std::isfinite(a.rotation) && std::isfinite(a.start_param) &&
                          std::isfinite(a.sweep);
                 }},
      e.geometry());
}

// The top of the drawing of `cp`, if the font has that glyph and it rises above the baseline.
std::optional<double> top_of(const std::unordered_map<char32_t, Box>& bounds, char32_t cp) {
  const auto it = bounds.find(cp);
  if (it == bounds.end() || it->second.empty() || it->second.max.y() <= 0) return std::nullopt;
  return it->second.max.y();
}

// `bounds` holds the lit drawing of every glyph in the font (stroke assembly does not move it).
void measure_metrics(const std::unordered_map<char32_t, Box>& bounds, FontMetrics& m,
                     double nominal_cap_height) {
  Box all;
  for (const auto& [cp, b] : bounds) all.add(b);
  m.ascender = all.empty() ? 0.0 : std::max(0.0, all.max.y());
  m.descender = all.empty() ? 0.0 : std::min(0.0, all.min.y());
  std::optional<double> cap = top_of(bounds, U'H');
  if (!cap) cap = top_of(bounds, U'I');
  m.cap_height = cap ? *cap : (m.ascender > 0 ? m.ascender : nominal_cap_height);
  const std::optional<double> x = top_of(bounds, U'x');
  m.x_height = x ? *x : m.cap_height;
  m.standard_height = m.cap_height;
}

}  // namespace

StrokeFont build_font(const std::string& source, FontMetrics metrics, std::vector<RawGlyph> glyphs,
                      const FontFormat& format, std::size_t end_line) {
  std::vector<Box> glyph_bounds;
  glyph_bounds.reserve(glyphs.size());
  Box extent;
  for (const RawGlyph& g : glyphs) {
    glyph_bounds.push_back(g.bounds());
    extent.add(glyph_bounds.back());
  }
  const double size = std::max({extent.width(), extent.height(), 1e-300});
  const double tolerance = kRelativeJoinTolerance * size;

  StrokeFont font(std::filesystem::path(source).stem().string(), source, metrics);
  StrokeAssembler assembler(tolerance);
  std::unordered_map<char32_t, Box> kept_bounds;
  kept_bounds.reserve(glyphs.size());
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    RawGlyph& raw = glyphs[i];
    Glyph glyph;
    glyph.code_point = raw.code_point;
    glyph.advance = raw.advance;
    if (format.advance_after_right_edge)
      glyph.advance = (glyph_bounds[i].empty() ? 0.0 : glyph_bounds[i].max.x()) +
                      *format.advance_after_right_edge;
    glyph.elements = assembler.assemble(raw);
    for (const Element& e : glyph.elements)
      if (!element_is_finite(e))
        throw FontFileError(source, raw.line,
                            "glyph " + describe_code_point(raw.code_point) + " has non-finite geometry");
    if (glyph.elements.empty() && !format.keep_empty_glyphs) continue;
    kept_bounds[raw.code_point] = glyph_bounds[i];
    font.add(std::move(glyph));
  }
  if (font.size() == 0)
    throw FontFileError(source, std::max<std::size_t>(end_line, 1), "the font has no glyphs");
  measure_metrics(kept_bounds, font.metrics(), format.nominal_cap_height);
  return font;
}

}  // namespace mark::loaders
