#pragma once
// Loaders for stroke-font files. Each maps the file's geometry to the same elements (lines,
// circular arcs), with the baseline at y = 0 and y up. A malformed file throws FontFileError naming
// the source, the line and what is wrong — never a partial font passed off as whole. Defects a
// loader can skip safely (an LFF vertex it cannot read) are reported through `warnings` with
// source and line.
#include <string>
#include <string_view>
#include <vector>

#include "fonts/stroke_font.hpp"

namespace mark {

using Warnings = std::vector<std::string>;

// Hershey James Hurt format (.jhf). Line i maps to U+0020 + i; hard-wrapped records are joined.
StrokeFont parse_jhf(std::string_view text, const std::string& source, Warnings* warnings = nullptr);
// LibreCAD font (.lff): polylines with bulge arcs, `C` glyph references.
StrokeFont parse_lff(std::string_view text, const std::string& source, Warnings* warnings = nullptr);
// QCAD font (.cxf): `L` lines, `A`/`AR` arcs in degrees.
StrokeFont parse_cxf(std::string_view text, const std::string& source, Warnings* warnings = nullptr);

// TrueType / OpenType outline font (.ttf, .otf) read through FreeType in font units: each glyph
// contour becomes a closed lit stroke of lines and circular arcs (Béziers biarc-fitted to within
// `tolerance_em` of the em), laser-off moves between contours. Code points of the BMP only.
// 1e-4 em is 1.4 µm on 10 mm capitals — below one step of a 16-bit galvo over a 110 mm field.
inline constexpr double kOutlineToleranceEm = 1e-4;

// What one outline font may cost. Opening reads only the character map and the metrics (and fits
// 'H', 'x' and the space, which give the heights); every other glyph is fitted when a text first
// uses it (fonts/glyph_source.hpp). Memory and fitting time grow with the elements a fit makes
// (96 bytes and about 5 µs each): DejaVu Sans's largest glyph makes 1 343 and all its 5 370
// glyphs 311 213; Liberation Sans's largest 419. A glyph or a font over its limit is refused.
struct OutlineLimits {
  std::size_t glyph_elements = 20'000;    // one glyph: about 2 MB and 0.1 s
  std::size_t font_elements = 1'000'000;  // every glyph one font has made: about 96 MB and 5 s
};

// The standard (cap) height must lie within this range of the em, else the font is refused: 0 or
// less leaves nothing to scale by, and a thousand em is a broken or hostile file, not a font.
inline constexpr double kMinStandardHeightEm = 0.01;
inline constexpr double kMaxStandardHeightEm = 10;

// Throws FontFileError naming the file: not a font FreeType reads, bitmap only, no Unicode
// character map, a character map that maps nothing, a standard height outside the range above,
// ascender below or descender above the baseline. A glyph that is malformed or over a limit is
// refused when it is first used (StrokeFont::find), naming the file, the character and the limit.
StrokeFont load_outline_font(const std::string& path, Warnings* warnings = nullptr,
                             double tolerance_em = kOutlineToleranceEm, OutlineLimits limits = {});
// The same from the file's bytes; `source` names the font in messages (the fuzz target).
StrokeFont parse_outline_font(std::string bytes, const std::string& source, Warnings* warnings = nullptr,
                              double tolerance_em = kOutlineToleranceEm, OutlineLimits limits = {});

// Reads a file and picks the parser by its extension (.jhf, .lff, .cxf; .ttf, .otf through
// load_outline_font). The font's name is the file's stem.
StrokeFont load_font_file(const std::string& path, Warnings* warnings = nullptr);

}  // namespace mark
