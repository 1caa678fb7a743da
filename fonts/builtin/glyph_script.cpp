#include "fonts/builtin/glyph_script.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "fonts/stroke_font.hpp"

namespace mark {
namespace {

constexpr double kJoinTol = 1e-9;    // an element starting this close to the pen continues the stroke
constexpr double kSnapTol = 0.01;    // a line ending this close to the next arc's start joins it
constexpr double kMinLength = 1e-6;  // shorter lit elements are typos, not strokes

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

// How many numbers a group of each command holds; 0 for an unknown command.
std::size_t arity(char command) {
  switch (command) {
    case 'M':
    case 'L': return 2;
    case 'A': return 5;
    case 'E': return 6;
    default: return 0;
  }
}

class ScriptParser {
 public:
  ScriptParser(char32_t code_point, double advance, std::string_view script) : script_(script) {
    glyph_.code_point = code_point;
    glyph_.advance = advance;
  }

  Glyph parse() {
    if (!(glyph_.advance > 0) || !std::isfinite(glyph_.advance))
      throw InputError("glyph " + describe_code_point(glyph_.code_point) + ": advance " +
                       std::to_string(glyph_.advance) + " is not positive");
    std::size_t i = 0;
    while (true) {
      while (i < script_.size() && is_space(script_[i])) ++i;
      if (i == script_.size()) break;
      if (is_letter(script_[i])) {
        start_command(i);
        ++i;
        continue;
      }
      if (command_ == 0) fail("coordinates before any command", token_at(i), i);
      const std::size_t start = i;
      while (i < script_.size() && !is_space(script_[i]) && !is_letter(script_[i])) ++i;
      run(script_.substr(start, i - start), start);
      command_has_group_ = true;
    }
    require_group();
    if (pending_move_) fail("script ends with a pen move", "M", pending_move_at_);
    return std::move(glyph_);
  }

 private:
  [[noreturn]] void fail(const std::string& what, std::string_view token, std::size_t at) const {
    throw InputError("glyph " + describe_code_point(glyph_.code_point) + " script: " + what +
                     " at '" + std::string(token) + "' (offset " + std::to_string(at) + ")");
  }

  std::string_view token_at(std::size_t i) const {
    std::size_t j = i;
    while (j < script_.size() && !is_space(script_[j])) ++j;
    return script_.substr(i, j - i);
  }

  void start_command(std::size_t at) {
    const char c = script_[at];
    if (arity(c) == 0) fail("unknown command", script_.substr(at, 1), at);
    require_group();
    command_ = c;
    command_at_ = at;
    command_has_group_ = false;
  }

  void require_group() const {
    if (command_ != 0 && !command_has_group_)
      fail("command without coordinates", script_.substr(command_at_, 1), command_at_);
  }

  std::vector<double> numbers(std::string_view group, std::size_t at) const {
    std::vector<double> out;
    std::size_t i = 0;
    while (true) {
      const char* first = group.data() + i;
      if (i < group.size() && group[i] == '+') ++first;  // from_chars rejects a leading '+'
      double v = 0;
      const auto [end, ec] = std::from_chars(first, group.data() + group.size(), v);
      if (ec != std::errc() || !std::isfinite(v)) fail("bad number", group, at);
      // Glyphs are drawn on a grid about 10 units tall: a coordinate, radius or angle beyond
      // ±1e6 is a typo, and one near 1e170 overflowed the geometry (found by fuzz_glyph_script).
      if (std::abs(v) > 1e6) fail("number outside -1000000 to 1000000", group, at);
      out.push_back(v);
      i = static_cast<std::size_t>(end - group.data());
      if (i == group.size()) break;
      if (group[i] != ',' || i + 1 == group.size()) fail("bad number", group, at);
      ++i;
    }
    if (out.size() != arity(command_))
      fail(std::string(1, command_) + " takes " + std::to_string(arity(command_)) +
               " numbers, got " + std::to_string(out.size()),
           group, at);
    return out;
  }

  void run(std::string_view group, std::size_t at) {
    const std::vector<double> v = numbers(group, at);
    switch (command_) {
      case 'M':
        pen_ = Point(v[0], v[1]);
        pending_move_ = true;
        pending_move_at_ = command_at_;
        return;
      case 'L':
        if (!pen_) fail("line with no pen position (start with M)", group, at);
        draw(Element::line(*pen_, Point(v[0], v[1])), group, at);
        return;
      case 'A':
        if (!(v[2] > 0)) fail("radius must be positive", group, at);
        draw(Element::arc(Point(v[0], v[1]), v[2], radians(v[3]), sweep(v[3], v[4], group, at)),
             group, at);
        return;
      case 'E':
        if (!(v[2] > 0) || !(v[3] > 0)) fail("radii must be positive", group, at);
        draw(Element::ellipse(Point(v[0], v[1]), v[2], v[3], 0.0, radians(v[4]),
                              sweep(v[4], v[5], group, at)),
             group, at);
        return;
    }
  }

  double sweep(double from_deg, double to_deg, std::string_view group, std::size_t at) const {
    const double sweep_deg = to_deg - from_deg;
    if (sweep_deg == 0 || std::abs(sweep_deg) > 360)
      fail("sweep must be in (0, 360] degrees", group, at);
    return radians(sweep_deg);
  }

  // Appends a lit element, preceded by a laser-off move from the previous lit element when it
  // does not start where that one ended. A line written to a few decimals that nearly reaches
  // the start of the arc after it is snapped onto it, so scripts need no 10-digit coordinates.
  void draw(const Element& element, std::string_view group, std::size_t at) {
    if (element.length() < kMinLength) fail("zero-length element", group, at);
    const Point start = element.start();
    if (pen_) {
      const double gap = (start - *pen_).norm();
      if (pending_move_) {
        if (gap >= kSnapTol) fail("element does not start at the point of the preceding M", group, at);
      } else if (gap > kJoinTol && gap < kSnapTol) {
        if (glyph_.elements.back().kind() != ElementKind::line)
          fail("element starts " + std::to_string(gap) +
                   " from the end of the arc before it: join exactly or move clearly",
               group, at);
        const Point line_start = glyph_.elements.back().start();
        if ((start - line_start).norm() < kMinLength) fail("zero-length element", group, at);
        glyph_.elements.back() = Element::line(line_start, start);
        last_lit_end_ = start;
      }
    }
    if (last_lit_end_ && (start - *last_lit_end_).norm() > kJoinTol)
      glyph_.elements.push_back(Element::line(*last_lit_end_, start, false));
    glyph_.elements.push_back(element);
    last_lit_end_ = element.end();
    pen_ = last_lit_end_;
    pending_move_ = false;
  }

  std::string_view script_;
  Glyph glyph_;
  char command_ = 0;  // the command the next group belongs to
  std::size_t command_at_ = 0;
  bool command_has_group_ = false;
  std::optional<Point> pen_;           // where the pen is, up or down
  std::optional<Point> last_lit_end_;  // where the last lit element ended
  bool pending_move_ = false;          // an M not yet followed by an element
  std::size_t pending_move_at_ = 0;
};

}  // namespace

Glyph parse_glyph_script(char32_t code_point, double advance, std::string_view script) {
  return ScriptParser(code_point, advance, script).parse();
}

}  // namespace mark
