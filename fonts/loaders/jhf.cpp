// Hershey fonts in James Hurt's format (.jhf), as Debian's hershey-fonts-data ships them.
//
// One record per glyph: columns 0-4 the Hershey glyph number, 5-7 the number of coordinate pairs
// (the bearing pair and every pen-up included), then the pairs, two characters each, a coordinate
// being its character minus 'R'. The first pair holds the left and right bearings; " R" lifts the
// pen. y grows downwards and the roman fonts stand on y = +9. Record i is the character U+0020+i.
// Data terms: see fonts/HERSHEY-ACKNOWLEDGEMENT.txt, which must ship with converted Hershey data.
// The USENET distribution hard-wraps long records; continuation lines are joined until the pair
// count is satisfied.
#include <string>

#include "fonts/error.hpp"
#include "fonts/loaders.hpp"
#include "fonts/loaders/font_builder.hpp"
#include "fonts/loaders/numbers.hpp"
#include "fonts/loaders/text_lines.hpp"

namespace mark {
namespace {

using loaders::LineReader;
using loaders::RawGlyph;

constexpr double kBaselineY = 9;    // file y of the baseline (y down)
constexpr double kCapHeight = 21;   // roman capitals: y −12 … +9
constexpr double kLineHeight = 32;  // Hershey's usual baseline-to-baseline distance
constexpr std::size_t kHeaderColumns = 8;
constexpr char32_t kFirstCodePoint = 0x20;
constexpr char32_t kLastCodePoint = 0xD7FF;  // records map to consecutive scalar values

// A record header: glyph number (cols 0-4) and pair count (cols 5-7), right-aligned digits. A
// continuation line can only look like this if its first eight characters are all digits
// (coordinates −34 … −25 in a row), which Hershey data never has.
bool looks_like_record_header(std::string_view line) {
  return line.size() >= kHeaderColumns && loaders::parse_field_integer(line.substr(0, 5)) &&
         loaders::parse_field_integer(line.substr(5, 3));
}

bool is_coordinate(char c) { return c > ' ' && c <= '~'; }

class JhfParser {
 public:
  JhfParser(std::string_view text, const std::string& source) : reader_(text), source_(source) {}

  StrokeFont parse() {
    std::vector<RawGlyph> glyphs;
    std::string_view line;
    std::size_t blank_line = 0;  // a blank line is fine only at the end of the file
    while (reader_.next(line)) {
      if (loaders::is_blank(line)) {
        if (!blank_line) blank_line = reader_.line_number();
        continue;
      }
      if (blank_line) fail(blank_line, "blank line between glyph records");
      const char32_t cp = kFirstCodePoint + static_cast<char32_t>(glyphs.size());
      if (cp > kLastCodePoint) fail(reader_.line_number(), "too many glyph records");
      glyphs.push_back(parse_record(line, cp));
    }

    FontMetrics metrics;
    metrics.baseline = kBaselineY;
    metrics.line_height = kLineHeight;
    if (!glyphs.empty()) metrics.word_spacing = glyphs.front().advance;  // the space, U+0020
    const loaders::FontFormat format{.nominal_cap_height = kCapHeight,
                                     .keep_empty_glyphs = true,
                                     .advance_after_right_edge = {}};
    return loaders::build_font(source_, metrics, std::move(glyphs), format, reader_.line_number());
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw FontFileError(source_, line, what);
  }

  RawGlyph parse_record(std::string_view line, char32_t cp) {
    const std::size_t record_line = reader_.line_number();
    if (line.size() < kHeaderColumns)
      fail(record_line, "record header " + loaders::quote(line) +
                            " is shorter than its 8 columns (glyph number, pair count)");
    if (!loaders::parse_field_integer(line.substr(0, 5)))
      fail(record_line,
           "bad glyph number " + loaders::quote(line.substr(0, 5)) + " in columns 1-5");
    const std::optional<long> pairs = loaders::parse_field_integer(line.substr(5, 3));
    if (!pairs)
      fail(record_line, "bad pair count " + loaders::quote(line.substr(5, 3)) + " in columns 6-8");
    if (*pairs < 1) fail(record_line, "pair count 0: a record needs at least its bearing pair");
    const std::size_t needed = 2 * static_cast<std::size_t>(*pairs);

    // The coordinate characters, joined over continuation lines if the record is wrapped.
    std::string_view body = line.substr(kHeaderColumns);
    std::string joined;
    std::size_t last_line = record_line;
    if (body.size() < needed) {
      joined.assign(body);
      std::string_view next;
      while (joined.size() < needed) {
        if (!reader_.peek(next) || looks_like_record_header(next) || loaders::is_blank(next))
          fail(record_line, "truncated record: pair count " + std::to_string(*pairs) + " needs " +
                                std::to_string(needed) + " coordinate characters, found " +
                                std::to_string(joined.size()));
        reader_.next(next);
        last_line = reader_.line_number();
        joined.append(next);
      }
      body = joined;
    }
    if (!loaders::is_blank(body.substr(needed)))
      fail(last_line, "record longer than its pair count " + std::to_string(*pairs) + " (" +
                          std::to_string(needed) + " coordinate characters) allows");
    return decode_pairs(body.substr(0, needed), cp, record_line);
  }

  RawGlyph decode_pairs(std::string_view body, char32_t cp, std::size_t line) const {
    RawGlyph g;
    g.code_point = cp;
    g.line = line;
    if (!is_coordinate(body[0]) || !is_coordinate(body[1]))
      fail(line, "bad bearing pair " + loaders::quote(body.substr(0, 2)));
    const int left = body[0] - 'R', right = body[1] - 'R';
    if (right < left)
      fail(line, "right bearing " + std::to_string(right) + " lies left of left bearing " +
                     std::to_string(left));
    g.advance = right - left;

    bool pen_down = false;
    Point last;
    for (std::size_t i = 2; i < body.size(); i += 2) {
      const char cx = body[i], cy = body[i + 1];
      if (cx == ' ' && cy == 'R') {
        pen_down = false;
        g.end_piece();
        continue;
      }
      if (!is_coordinate(cx) || !is_coordinate(cy))
        fail(line, "pair " + std::to_string(i / 2 + 1) + " " + loaders::quote(body.substr(i, 2)) +
                       " is neither a point nor the pen-up ' R'");
      // Origin on the left bearing, y up from the baseline.
      const Point p((cx - 'R') - left, kBaselineY - (cy - 'R'));
      if (pen_down) g.elements.push_back(Element::line(last, p));
      last = p;
      pen_down = true;
    }
    g.end_piece();
    return g;
  }

  LineReader reader_;
  const std::string& source_;
};

}  // namespace

StrokeFont parse_jhf(std::string_view text, const std::string& source, Warnings*) {
  return JhfParser(text, source).parse();
}

}  // namespace mark
