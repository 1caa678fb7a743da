#pragma once
// What LibreCAD's .lff and QCAD's .cxf files share: the `# Key: value` header block, the `[...]`
// glyph headers, and the spacing rules (advance = rightmost point + LetterSpacing; text height 9
// units; line spacing 9 × 1.6 × LineSpacingFactor, as LibreCAD lays text out).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fonts/loaders.hpp"
#include "fonts/loaders/raw_glyph.hpp"
#include "fonts/loaders/text_lines.hpp"

namespace mark::loaders {

inline constexpr double kLibreCadTextHeight = 9;
inline constexpr double kLibreCadLineSpacing = 1.6;  // baseline distance per unit of text height

struct LffCxfHeader {
  // LibreCAD's defaults for a file that does not state them.
  double letter_spacing = 3;
  double word_spacing = 6.75;
  double line_spacing_factor = 1;
  TextEncoding encoding = TextEncoding::utf8;
};

// One `#` line. `# Key: value` lines with a known key (LetterSpacing, WordSpacing,
// LineSpacingFactor, Encoding; case-insensitive) are read and checked; every other `#` line is a
// comment. Throws FontFileError for a bad value.
void read_header_line(std::string_view line, LffCxfHeader& header, const std::string& source,
                      std::size_t line_number);

struct GlyphHeader {
  char32_t code_point = 0;
  bool literal = false;   // `[c]` (old CXF): the character itself between the brackets
  std::string_view rest;  // after the ']' (the character, or an old CXF element count)
};

// `[XXXX] c` (1-6 hex digits) and `[#XXXX]`; with `allow_literal` also `[c] N`. A doubled
// opening bracket (`[[038c]`, a typo in LibreCAD's greek_ol.lff) is accepted with a warning.
GlyphHeader parse_glyph_header(std::string_view line, bool allow_literal, const std::string& source,
                               std::size_t line_number, TextEncoding encoding, Warnings* warnings);

// "source:line: what", the form every loader warning takes.
void warn(Warnings* warnings, const std::string& source, std::size_t line, const std::string& what);

// Drawing lines outside any glyph (LibreCAD's syastro.lff has a stray block after a blank line).
// LibreCAD and QCAD skip them silently; we skip them with one warning per block.
class OrphanLines {
 public:
  void add(std::size_t line) {
    if (count_++ == 0) first_ = line;
  }
  // Reports the block that just ended, if any.
  void flush(Warnings* warnings, const std::string& source) {
    if (count_ != 0) report(warnings, source);
  }

 private:
  void report(Warnings* warnings, const std::string& source);
  std::size_t first_ = 0;
  std::size_t count_ = 0;
};

// Metrics the header states, before the measured ones are added.
FontMetrics header_metrics(const LffCxfHeader& header);

// The warning for a glyph defined twice (both formats keep the first, as LibreCAD does).
void warn_duplicate_glyph(Warnings* warnings, const std::string& source, std::size_t line,
                          char32_t code_point, std::size_t first_line);

// The font from its glyphs, with the header's metrics and LibreCAD's spacing rules: nominal
// text height 9, advance = rightmost point + LetterSpacing.
StrokeFont build_librecad_font(const std::string& source, const LffCxfHeader& header,
                               std::vector<RawGlyph> glyphs, std::size_t last_line);

}  // namespace mark::loaders
