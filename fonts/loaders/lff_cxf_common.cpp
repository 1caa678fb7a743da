#include "fonts/loaders/lff_cxf_common.hpp"

#include <algorithm>
#include <cctype>

#include "fonts/error.hpp"
#include "fonts/loaders/font_builder.hpp"
#include "fonts/loaders/numbers.hpp"
#include "fonts/utf8.hpp"

namespace mark::loaders {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

TextEncoding encoding_named(std::string_view value, const std::string& source, std::size_t line) {
  std::string name = lower(value);
  std::erase_if(name, [](char c) { return c == '-' || c == '_' || c == ' '; });
  if (name == "utf8" || name == "ascii" || name == "usascii") return TextEncoding::utf8;
  if (name == "iso88591" || name == "latin1") return TextEncoding::latin1;
  throw FontFileError(source, line,
                      "unsupported Encoding " + quote(value) + " (UTF-8 or ISO-8859-1 expected)");
}

}  // namespace

void read_header_line(std::string_view line, LffCxfHeader& header, const std::string& source,
                      std::size_t line_number) {
  std::string_view body = trim(line);
  body.remove_prefix(1);  // the '#'
  const std::size_t colon = body.find(':');
  if (colon == std::string_view::npos) return;  // a comment
  const std::string key = lower(trim(body.substr(0, colon)));
  const std::string_view value = trim(body.substr(colon + 1));
  if (key == "letterspacing") {
    header.letter_spacing = require_number(value, source, line_number, "LetterSpacing");
  } else if (key == "wordspacing") {
    header.word_spacing = require_number(value, source, line_number, "WordSpacing");
    if (header.word_spacing < 0)
      throw FontFileError(source, line_number, "WordSpacing " + quote(value) + " is negative");
  } else if (key == "linespacingfactor") {
    header.line_spacing_factor = require_number(value, source, line_number, "LineSpacingFactor");
    if (!(header.line_spacing_factor > 0))
      throw FontFileError(source, line_number,
                          "LineSpacingFactor " + quote(value) + " is not positive");
  } else if (key == "encoding") {
    header.encoding = encoding_named(value, source, line_number);
  }
}

GlyphHeader parse_glyph_header(std::string_view line, bool allow_literal, const std::string& source,
                               std::size_t line_number, TextEncoding encoding, Warnings* warnings) {
  std::string_view s = trim(line);
  const auto bad = [&](const std::string& why) {
    throw FontFileError(source, line_number, "bad glyph header " + quote(s) + ": " + why);
  };
  if (!allow_literal && s.size() > 1 && s[1] == '[') {
    warn(warnings, source, line_number, "glyph header " + quote(s) + " has a doubled '['");
    s.remove_prefix(1);
  }
  // Search for ']' from the third byte so that `[]]` (old CXF, the character ']') has content.
  const std::size_t close = s.find(']', 2);
  if (close == std::string_view::npos) bad("no closing ']'");
  const std::string_view content = s.substr(1, close - 1);
  GlyphHeader h;
  h.rest = trim(s.substr(close + 1));

  if (content.front() == '#' && content.size() > 1) {  // `[#]` is the old CXF form of '#'
    const auto cp = parse_hex_code_point(content.substr(1));
    if (!cp) bad("'#' must be followed by 1-6 hex digits of a Unicode code point");
    h.code_point = *cp;
    return h;
  }
  if (allow_literal) {
    char32_t literal = 0;
    bool single = false;
    if (encoding == TextEncoding::latin1) {
      single = content.size() == 1;
      if (single) literal = static_cast<unsigned char>(content[0]);
    } else {
      const std::u32string chars = decode_utf8(content, "glyph header");  // line checked already
      single = chars.size() == 1;
      if (single) literal = chars[0];
    }
    if (single) {
      h.code_point = literal;
      h.literal = true;
      return h;
    }
  }
  const auto cp = parse_hex_code_point(content);
  if (!cp) bad("expected 1-6 hex digits of a Unicode code point");
  h.code_point = *cp;
  return h;
}

void warn(Warnings* warnings, const std::string& source, std::size_t line,
          const std::string& what) {
  if (warnings) warnings->push_back(source + ":" + std::to_string(line) + ": " + what);
}

FontMetrics header_metrics(const LffCxfHeader& header) {
  FontMetrics m;
  m.baseline = 0;
  m.line_height = kLibreCadTextHeight * kLibreCadLineSpacing * header.line_spacing_factor;
  // Glyph advances already include LetterSpacing; nothing extra is asked of the layout.
  m.letter_spacing = 0;
  m.word_spacing = header.word_spacing;
  return m;
}

void OrphanLines::report(Warnings* warnings, const std::string& source) {
  warn(warnings, source, first_,
       "ignored " + std::to_string(count_) + (count_ == 1 ? " line" : " lines") +
           " outside any glyph (no '[XXXX]' header above since the last blank line)");
  count_ = 0;
}

void warn_duplicate_glyph(Warnings* warnings, const std::string& source, std::size_t line,
                          char32_t code_point, std::size_t first_line) {
  warn(warnings, source, line,
       "duplicate glyph " + describe_code_point(code_point) + " ignored (first defined at line " +
           std::to_string(first_line) + ")");
}

StrokeFont build_librecad_font(const std::string& source, const LffCxfHeader& header,
                               std::vector<RawGlyph> glyphs, std::size_t last_line) {
  return build_font(source, header_metrics(header), std::move(glyphs),
                    {.nominal_cap_height = kLibreCadTextHeight,
                     .advance_after_right_edge = header.letter_spacing},
                    last_line);
}

}  // namespace mark::loaders
