// TrueType / OpenType outline fonts through FreeType: opening one reads its character map and
// metrics; its glyphs are made on first use by OutlineGlyphs (loaders/outline_glyphs.hpp), each
// contour a closed lit stroke of lines and circular arcs in font units, baseline 0, y up — the
// same elements the stroke-font loaders produce, so layout, hatching and the machines need
// nothing new.
#include <ft2build.h>
#include FT_TRUETYPE_TABLES_H

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "fonts/error.hpp"
#include "fonts/loaders.hpp"
#include "fonts/loaders/outline_glyphs.hpp"
#include "fonts/loaders/read_font_file.hpp"

namespace mark {
namespace {

std::string em_figure(double units, double units_per_em) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%g font units (%.4g em)", units, units / units_per_em);
  return buf;
}

}  // namespace

StrokeFont parse_outline_font(std::string bytes, const std::string& source, Warnings* /*warnings*/,
                              double tolerance_em, OutlineLimits limits) {
  const auto fail = [&](const std::string& what) { throw FontFileError(source, 0, what); };
  auto glyphs = std::make_shared<loaders::OutlineGlyphs>(std::move(bytes), source, tolerance_em, limits);
  if (glyphs->code_point_count() == 0) fail("the font maps no character of the Basic Multilingual Plane to a glyph");
  const FT_Face face = glyphs->face();
  const double em = face->units_per_EM;

  FontMetrics metrics;
  metrics.ascender = face->ascender;
  metrics.descender = face->descender;
  metrics.line_height = face->height;
  if (metrics.ascender < 0 || metrics.descender > 0)
    fail("ascender " + std::to_string(face->ascender) + " and descender " + std::to_string(face->descender) +
         " font units: the ascender must not lie below the baseline nor the descender above it");

  // Heights from the glyphs themselves (what a user measures on the mark), else the OS/2 table.
  // These few glyphs are made now; every other one when a text uses it.
  const auto* os2 = static_cast<const TT_OS2*>(FT_Get_Sfnt_Table(face, FT_SFNT_OS2));
  const auto top_of = [&](char32_t cp, double fallback) {
    const Glyph* g = glyphs->find(cp);
    const Box b = g ? g->bounds() : Box{};
    return b.empty() ? fallback : b.max.y();
  };
  metrics.cap_height = top_of(U'H', os2 && os2->sCapHeight > 0 ? os2->sCapHeight : face->ascender);
  metrics.x_height = top_of(U'x', os2 && os2->sxHeight > 0 ? os2->sxHeight : metrics.cap_height * 0.7);
  metrics.standard_height = metrics.cap_height;
  const double h = metrics.standard_height;
  if (!(h >= kMinStandardHeightEm * em && h <= kMaxStandardHeightEm * em)) {
    char range[64];
    std::snprintf(range, sizeof range, "%g .. %g em", kMinStandardHeightEm, kMaxStandardHeightEm);
    fail("cap height " + em_figure(h, em) + " is no usable standard height (allowed " + range + ")");
  }
  const Glyph* space = glyphs->find(U' ');
  metrics.word_spacing = space ? space->advance : em / 4.0;
  return StrokeFont(std::filesystem::path(source).stem().string(), source, metrics, std::move(glyphs));
}

StrokeFont load_outline_font(const std::string& path, Warnings* warnings, double tolerance_em,
                             OutlineLimits limits) {
  return parse_outline_font(loaders::read_font_file(path), path, warnings, tolerance_em, limits);
}

}  // namespace mark
