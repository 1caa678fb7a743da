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
StrokeFont load_outline_font(const std::string& path, Warnings* warnings = nullptr,
                             double tolerance_em = kOutlineToleranceEm);

// Reads a file and picks the parser by its extension (.jhf, .lff, .cxf; .ttf, .otf through
// load_outline_font). The font's name is the file's stem.
StrokeFont load_font_file(const std::string& path, Warnings* warnings = nullptr);

}  // namespace mark
