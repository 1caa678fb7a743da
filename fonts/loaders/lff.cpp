// LibreCAD fonts (.lff): after the `#` header, each glyph is `[XXXX] c` followed by lines up to a
// blank line. A line is a polyline `x,y;x,y;...` whose vertices may carry a third field `A<bulge>`
// — the bulge (tan of a quarter of the sweep, positive counter-clockwise) of the segment that
// ENDS at that vertex — or `C<hex>`, which draws another glyph's strokes at that point (the glyph
// may be defined further down). Coordinates: baseline y = 0, y up, capitals 9 high.
#include <cmath>
#include <cstdio>
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

// A bulge this small bends a segment by less than 1e-9 of its length: a straight line.
constexpr double kStraightBulge = 1e-9;
// Glyph references can nest and repeat; a file whose expansion exceeds this is refused rather
// than allowed to eat the machine's memory.
constexpr std::size_t kMaxExpandedElements = 2'000'000;

struct Reference {
  char32_t target;
  std::size_t before_piece;  // drawn before the glyph's own piece with this index
  std::size_t line;
};

struct LffGlyph {
  RawGlyph raw;
  std::vector<Reference> references;
};

class LffParser {
 public:
  LffParser(std::string_view text, const std::string& source, Warnings* warnings)
      : reader_(text), source_(source), warnings_(warnings) {}

  StrokeFont parse() {
    std::string_view line;
    LffGlyph* current = nullptr;  // the glyph whose body is being read
    LffGlyph discarded;           // body of a duplicate glyph: checked, then dropped
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
        current = nullptr;
      } else if (t.front() == '#') {
        loaders::read_header_line(t, header_, source_, n);
      } else if (t.front() == '[') {
        current = start_glyph(t, n, discarded);
      } else if (t.front() == 'C') {
        read_reference(t, n, *current);
      } else {
        read_polyline(t, n, current->raw);
      }
    }
    orphans_.flush(warnings_, source_);
    resolve_references();

    std::vector<RawGlyph> raw;
    raw.reserve(glyphs_.size());
    for (LffGlyph& g : glyphs_) raw.push_back(std::move(g.raw));
    return loaders::build_librecad_font(source_, header_, std::move(raw), reader_.line_number());
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw FontFileError(source_, line, what);
  }

  LffGlyph* start_glyph(std::string_view t, std::size_t n, LffGlyph& discarded) {
    const loaders::GlyphHeader h =
        loaders::parse_glyph_header(t, false, source_, n, header_.encoding, warnings_);
    const auto [it, fresh] = index_.try_emplace(h.code_point, glyphs_.size());
    if (!fresh) {
      // LibreCAD keeps the first definition.
      loaders::warn_duplicate_glyph(warnings_, source_, n, h.code_point, glyphs_[it->second].raw.line);
      discarded = LffGlyph{};
      return &discarded;
    }
    LffGlyph& g = glyphs_.emplace_back();
    g.raw.code_point = h.code_point;
    g.raw.line = n;
    return &g;
  }

  void read_reference(std::string_view t, std::size_t n, LffGlyph& g) {
    const auto target = loaders::parse_hex_code_point(t.substr(1));
    if (!target) fail(n, "bad glyph reference " + quote(t) + " (expected C and 1-6 hex digits)");
    g.raw.end_piece();
    g.references.push_back({*target, g.raw.piece_ends.size(), n});
  }

  // A vertex "x,y" or "x,y,A<bulge>" (spaces allowed around the parts); false, with a warning,
  // when it is neither. Read with a cursor: unicode.lff has 160 000 of them.
  bool read_vertex(std::string_view text, std::size_t n, Point& p, double& bulge) {
    std::size_t i = 0;
    const auto skip_spaces = [&] {
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    };
    const auto take = [&](char c) {
      skip_spaces();
      if (i >= text.size() || text[i] != c) return false;
      ++i;
      skip_spaces();
      return true;
    };
    const auto number = [&](double& value) {
      std::size_t used = 0;
      const loaders::NumberStatus s = loaders::scan_number(text.substr(i), used, value);
      if (s == loaders::NumberStatus::malformed) return false;
      if (s != loaders::NumberStatus::ok)
        fail(n, "number " + quote(text.substr(i, used)) + " in vertex " + quote(text) + " " +
                    loaders::describe(s));
      i += used;
      return true;
    };
    double x = 0, y = 0, b = 0;
    bool ok = number(x) && take(',') && number(y);
    skip_spaces();
    if (ok && i < text.size()) ok = take(',') && take('A') && number(b);
    skip_spaces();
    if (!ok || i != text.size()) {
      loaders::warn(warnings_, source_, n, "skipped malformed vertex " + quote(text));
      return false;
    }
    p = Point(x, y);
    bulge = b;
    return true;
  }

  void read_polyline(std::string_view t, std::size_t n, RawGlyph& g) {
    g.end_piece();
    bool have_previous = false;
    Point previous;
    loaders::for_each_field(t, ';', [&](std::string_view vertex) {
      vertex = loaders::trim(vertex);
      if (vertex.empty()) return;  // "x,y;" — LibreCAD skips empty parts too
      Point p;
      double bulge = 0;
      if (!read_vertex(vertex, n, p, bulge)) return;
      if (have_previous) g.elements.push_back(segment(previous, p, bulge, n));
      previous = p;
      have_previous = true;
    });
    g.end_piece();
  }

  Element segment(const Point& a, const Point& b, double bulge, std::size_t n) const {
    if (std::abs(bulge) <= kStraightBulge) return Element::line(a, b);
    try {
      return Element::bulge(a, b, bulge);
    } catch (const InputError& e) {
      fail(n, std::string("bulge arc: ") + e.what());
    }
  }

  // Replaces every `C` reference by the referenced glyph's pieces, deepest first, without
  // recursion (reference chains may be long). A reference to a missing glyph or one that leads
  // back to its own glyph is an error at the reference's line.
  void resolve_references() {
    enum class State : unsigned char { pending, resolving, done };
    std::vector<State> state(glyphs_.size(), State::pending);
    std::size_t total = 0;
    for (const LffGlyph& g : glyphs_) total += g.raw.elements.size();

    struct Frame {
      std::size_t glyph;
      std::size_t next_reference;
    };
    std::vector<Frame> stack;
    for (std::size_t root = 0; root < glyphs_.size(); ++root) {
      if (state[root] != State::pending) continue;
      stack.push_back({root, 0});
      state[root] = State::resolving;
      while (!stack.empty()) {
        Frame& f = stack.back();
        LffGlyph& g = glyphs_[f.glyph];
        if (f.next_reference < g.references.size()) {
          const Reference& r = g.references[f.next_reference++];
          const auto it = index_.find(r.target);
          if (it == index_.end())
            fail(r.line, "glyph reference C" + hex(r.target) + " in " +
                             describe_code_point(g.raw.code_point) + ": the font has no glyph " +
                             describe_code_point(r.target));
          if (state[it->second] == State::resolving)
            fail(r.line, "glyph reference cycle: C" + hex(r.target) + " in " +
                             describe_code_point(g.raw.code_point) + " leads back to " +
                             describe_code_point(g.raw.code_point));
          if (state[it->second] == State::pending) {
            state[it->second] = State::resolving;
            stack.push_back({it->second, 0});
          }
          continue;
        }
        total += expand(g, total);
        state[f.glyph] = State::done;
        stack.pop_back();
      }
    }
  }

  // Splices the (resolved) referenced glyphs into g; returns how many elements that added.
  std::size_t expand(LffGlyph& g, std::size_t total_so_far) {
    if (g.references.empty()) return 0;
    RawGlyph out;
    out.code_point = g.raw.code_point;
    out.line = g.raw.line;
    std::size_t piece = 0, begin = 0, added = 0;
    const auto copy_own_pieces_until = [&](std::size_t piece_index) {
      for (; piece < piece_index && piece < g.raw.piece_ends.size(); ++piece) {
        const std::size_t end = g.raw.piece_ends[piece];
        out.elements.insert(out.elements.end(), g.raw.elements.begin() + begin,
                            g.raw.elements.begin() + end);
        out.piece_ends.push_back(out.elements.size());
        begin = end;
      }
    };
    for (const Reference& r : g.references) {
      copy_own_pieces_until(r.before_piece);
      const RawGlyph& target = glyphs_[index_.at(r.target)].raw;
      added += target.elements.size();
      if (total_so_far + added > kMaxExpandedElements)
        fail(r.line, "glyph references expand to more than " +
                         std::to_string(kMaxExpandedElements) + " elements");
      out.append_pieces(target);
    }
    copy_own_pieces_until(g.raw.piece_ends.size());
    g.raw = std::move(out);
    g.references.clear();
    return added;
  }

  static std::string hex(char32_t cp) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%04X", static_cast<unsigned>(cp));
    return buf;
  }

  LineReader reader_;
  const std::string& source_;
  Warnings* warnings_;
  loaders::LffCxfHeader header_;
  loaders::OrphanLines orphans_;
  std::vector<LffGlyph> glyphs_;
  std::unordered_map<char32_t, std::size_t> index_;
};

}  // namespace

StrokeFont parse_lff(std::string_view text, const std::string& source, Warnings* warnings) {
  return LffParser(text, source, warnings).parse();
}

}  // namespace mark
