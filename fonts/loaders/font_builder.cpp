#include "fonts/loaders/font_builder.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <variant>

#include "fonts/error.hpp"
#include "fonts/loaders/strokes.hpp"
#include "fonts/overloaded.hpp"
#include "fonts/stroke_join.hpp"

namespace mark::loaders {
namespace {

bool finite(const Point& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

// Loader input is range-checked, so this never fires; it keeps a geometry bug from ever handing
// NaN coordinates to a scanner.
bool element_is_finite(const Element& e) {
  return std::visit(Overloaded{[](const Line& l) { return finite(l.start) && finite(l.end); },
                               [](const CircularArc& a) {
                                 return finite(a.center) && std::isfinite(a.radius) &&
                                        std::isfinite(a.start_angle) && std::isfinite(a.sweep);
                               },
                               [](const EllipticalArc& a) {
                                 return finite(a.center) && std::isfinite(a.rx) &&
                                        std::isfinite(a.ry) && std::isfinite(a.rotation) &&
                                        std::isfinite(a.start_param) && std::isfinite(a.sweep);
                               }},
                    e.geometry());
}

// What the metrics are measured from: the lit drawing of all kept glyphs, and of the few that
// define heights (stroke assembly does not move the drawing, so the raw bounds are the glyphs').
class MetricSample {
 public:
  void add(char32_t cp, const Box& b) {
    all_.add(b);
    if (cp == U'H') h_ = b;
    if (cp == U'I') i_ = b;
    if (cp == U'x') x_ = b;
  }

  void measure(FontMetrics& m, double nominal_cap_height) const {
    m.ascender = all_.empty() ? 0.0 : std::max(0.0, all_.max.y());
    m.descender = all_.empty() ? 0.0 : std::min(0.0, all_.min.y());
    std::optional<double> cap = top(h_);
    if (!cap) cap = top(i_);
    m.cap_height = cap ? *cap : (m.ascender > 0 ? m.ascender : nominal_cap_height);
    const std::optional<double> x = top(x_);
    m.x_height = x ? *x : m.cap_height;
    m.standard_height = m.cap_height;
  }

 private:
  // The top of a glyph's drawing, if it rises above the baseline.
  static std::optional<double> top(const Box& b) {
    if (b.empty() || b.max.y() <= 0) return std::nullopt;
    return b.max.y();
  }

  Box all_, h_, i_, x_;
};

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
  // Pieces join within the shared fraction of the letter height (fonts/stroke_join.hpp): the
  // font's design cap height where the format has one, else the height of its drawing.
  const double height = format.nominal_cap_height > 0 ? format.nominal_cap_height
                                                      : std::max(extent.height(), 1e-300);
  const double tolerance = join_tolerance(height);

  StrokeFont font(std::filesystem::path(source).stem().string(), source, metrics);
  StrokeAssembler assembler(tolerance);
  MetricSample sample;
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
        throw FontFileError(
            source, raw.line,
            "glyph " + describe_code_point(raw.code_point) + " has non-finite geometry");
    if (glyph.elements.empty() && !format.keep_empty_glyphs) continue;
    sample.add(raw.code_point, glyph_bounds[i]);
    font.add(std::move(glyph));
  }
  if (font.size() == 0)
    throw FontFileError(source, std::max<std::size_t>(end_line, 1), "the font has no glyphs");
  sample.measure(font.metrics(), format.nominal_cap_height);
  return font;
}

}  // namespace mark::loaders
