// QCAD fonts (.cxf): after the `#` header, each glyph is `[XXXX] c`, `[#XXXX]` or the old `[c] N`
// followed by records up to a blank line: `L x1,y1,x2,y2` a line, `A cx,cy,r,a1,a2` an arc
// counter-clockwise from angle a1 to a2 (degrees, through 360 if a2 < a1; a1 == a2 is a full
// circle), `AR ...` the same clockwise. Coordinates: baseline y = 0, y up, capitals 9 high.
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "fonts/error.hpp"
#include "fonts/loaders.hpp"
#include "fonts/loaders/font_builder.hpp"
#include "fonts/loaders/lff_cxf_common.hpp"
#include "fonts/loaders/numbers.hpp"

namespace mark {
namespace {

using loaders::LineReader;
using loaders::quote;
using loaders::RawGlyph;

constexpr double kDegree = std::numbers::pi / 180;

// Sweep in degrees from a1 to a2 going counter-clockwise, in (0, 360]: equal angles (modulo 360)
// are a full circle.
double ccw_sweep_deg(double a1, double a2) {
  double d = std::fmod(a2 - a1, 360.0);
  if (d <= 0) d += 360;
  return d;
}

struct DeclaredCount {
  std::size_t declared_count = 0;  // old `[c] N` headers state their element count
  bool has_count = false;
};

class CxfParser {
 public:
  CxfParser(std::string_view text, const std::string& source, Warnings* warnings)
      : reader_(text), source_(source), warnings_(warnings) {}

  StrokeFont parse() {
    std::string_view line;
    RawGlyph* current = nullptr;
    RawGlyph discarded;
    while (reader_.next(line)) {
      const std::size_t n = reader_.line_number();
      loaders::check_text_line(line, header_.encoding, source_, n);
      const std::string_view t = loaders::trim(line);
      if (!t.empty() && t.front() != '#' && t.front() != '[' && !current) {
        orphans_.add(n);
        continue;
      }
      orphans_.flush(warnings_, source_);
      if (t.empty()) {
        if (current) check_count(*current);
        current = nullptr;
      } else if (t.front() == '#') {
        loaders::read_header_line(t, header_, source_, n);
      } else if (t.front() == '[') {
        if (current) check_count(*current);
        current = start_glyph(t, n, discarded);
      } else {
        read_record(t, n, *current);
      }
    }
    if (current) check_count(*current);
    orphans_.flush(warnings_, source_);

    return loaders::build_librecad_font(source_, header_, std::move(glyphs_), reader_.line_number());
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw FontFileError(source_, line, what);
  }

  RawGlyph* start_glyph(std::string_view t, std::size_t n, RawGlyph& discarded) {
    const loaders::GlyphHeader h =
        loaders::parse_glyph_header(t, true, source_, n, header_.encoding, warnings_);
    DeclaredCount info;
    if (h.literal && !h.rest.empty()) {
      const auto count = loaders::parse_field_integer(h.rest);
      if (!count) fail(n, "bad element count " + quote(h.rest) + " after the glyph's character");
      info = {static_cast<std::size_t>(*count), true};
    }
    const auto [it, fresh] = index_.try_emplace(h.code_point, glyphs_.size());
    if (!fresh) {
      loaders::warn_duplicate_glyph(warnings_, source_, n, h.code_point, glyphs_[it->second].line);
      discarded = RawGlyph{};
      discarded.line = n;
      current_info_ = info;
      return &discarded;
    }
    RawGlyph& g = glyphs_.emplace_back();
    g.code_point = h.code_point;
    g.line = n;
    current_info_ = info;
    return &g;
  }

  // QCAD ignores the count of old headers; a mismatch is reported, not fatal.
  void check_count(const RawGlyph& g) {
    if (current_info_.has_count && current_info_.declared_count != g.piece_ends.size())
      loaders::warn(warnings_, source_, g.line,
                    "glyph " + describe_code_point(g.code_point) + " declares " +
                        std::to_string(current_info_.declared_count) + " elements but has " +
                        std::to_string(g.piece_ends.size()));
    current_info_ = {};
  }

  void read_record(std::string_view t, std::size_t n, RawGlyph& g) {
    std::size_t letters = 0;
    while (letters < t.size() && t[letters] >= 'A' && t[letters] <= 'Z') ++letters;
    const std::string_view kind = t.substr(0, letters);
    const bool line = kind == "L", ccw_arc = kind == "A", cw_arc = kind == "AR";
    if (!line && !ccw_arc && !cw_arc)
      fail(n, "unknown record " + quote(t) + " (expected L, A or AR)");
    const std::size_t wanted = line ? 4 : 5;

    std::string_view fields[5];
    std::size_t count = 0;
    const std::string_view values = loaders::trim(t.substr(letters));
    if (!values.empty())
      loaders::for_each_field(values, ',', [&](std::string_view f) {
        if (count < wanted) fields[count] = loaders::trim(f);
        ++count;
      });
    if (count != wanted)
      fail(n, std::string(kind) + " record " + quote(t) + " needs " + std::to_string(wanted) +
                  " numbers, found " + std::to_string(count));
    double v[5] = {};
    for (std::size_t i = 0; i < wanted; ++i)
      v[i] = loaders::require_number(fields[i], source_, n, "value");

    if (line) {
      g.elements.push_back(Element::line({v[0], v[1]}, {v[2], v[3]}));
    } else {
      if (!(v[2] > 0)) fail(n, "arc " + quote(t) + " has a non-positive radius");
      const double sweep_deg = ccw_arc ? ccw_sweep_deg(v[3], v[4]) : -ccw_sweep_deg(v[4], v[3]);
      g.elements.push_back(
          Element::arc({v[0], v[1]}, v[2], std::fmod(v[3], 360.0) * kDegree, sweep_deg * kDegree));
    }
    g.end_piece();
  }

  LineReader reader_;
  const std::string& source_;
  Warnings* warnings_;
  loaders::LffCxfHeader header_;
  loaders::OrphanLines orphans_;
  std::vector<RawGlyph> glyphs_;
  std::unordered_map<char32_t, std::size_t> index_;
  DeclaredCount current_info_;  // of the glyph being read
};

}  // namespace

StrokeFont parse_cxf(std::string_view text, const std::string& source, Warnings* warnings) {
  return CxfParser(text, source, warnings).parse();
}

}  // namespace mark
