#include "fonts/builtin/glyph_script.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "fonts/error.hpp"
#include "fonts/stroke_font.hpp"

namespace mark {
namespace {

constexpr double kJoinTol = 1e-9;       // an element starting this close to the pen is connected
constexpr double kSnapTol = 0.01;       // a line ending this close to the next arc's start joins it
constexpr double kMinLength = 1e-6;     // shorter lit elements are typos, not strokes

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

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
  ScriptParser(char32_t code_point, double advance, std::string_view script)
      : script_(script) {
    glyph_.code_point = code_point;
    glyph_.advance = advance;
  }

  Glyph parse() {
    if (!(glyph_.advance > 0) || !std::isfinite(glyph_.advance))
      fail("advance " + std::to_string(glyph_.advance) + " is not positive", "", 0);
    char command = 0;
    std::size_t i = 0;
    while (true) {
      while (i < script_.size() && std::isspace(static_cast<unsigned char>(script_[i]))) ++i;
      if (i == script_.size()) break;
      const char c = script_[i];
      if (std::isalpha(static_cast<unsigned char>(c))) {
        if (arity(c) == 0) fail("unknown command", std::string(1, c), i);
        if (command != 0 && !had_group_) fail("command without coordinates", std::string(1, command), command_at_);
        command = c;
        command_at_ = i;
        had_group_ = false;
        ++i;
        continue;
      }
      if (command == 0) fail("coordinates before any command", token_at(i), i);
      const std::size_t start = i;
      while (i < script_.size() && !std::isspace(static_cast<unsigned char>(script_[i])) &&
             !std::isalpha(static_cast<unsigned char>(script_[i])))
        ++i;
      run(command, script_.substr(start, i - start), start);
      had_group_ = true;
    }
    if (command != 0 && !had_group_) fail("command without coordinates", std::string(1, command), command_at_);
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
    while (j < script_.size() && !std::isspace(static_cast<unsigned char>(script_[j]))) ++j;
    return script_.substr(i, j - i);
  }

  std::vector<double> numbers(char command, std::string_view group, std::size_t at) const {
    std::vector<double> out;
    std::size_t i = 0;
    while (true) {
      double v = 0;
      const char* first = group.data() + i;
      const char* last = group.data() + group.size();
      if (i < group.size() && group[i] == '+') ++first;  // from_chars rejects a leading '+'
      const auto [end, ec] = std::from_chars(first, last, v);
      if (ec != std::errc() || !std::isfinite(v)) fail("bad number", group, at);
      out.push_back(v);
      i = static_cast<std::size_t>(end - group.data());
      if (i == group.size()) break;
      if (group[i] != ',' || i + 1 == group.size()) fail("bad number", group, at);
      ++i;
    }
    if (out.size() != arity(command))
      fail(std::string(1, command) + " takes " + std::to_string(arity(command)) + " numbers, got " +
               std::to_string(out.size()),
           group, at);
    return out;
  }

  void run(char command, std::string_view group, std::size_t at) {
    const std::vector<double> v = numbers(command, group, at);
    switch (command) {
      case 'M':
        pen_ = Point(v[0], v[1]);
        pending_move_ = true;
        pending_move_at_ = at;
        return;
      case 'L':
        if (!pen_) fail("line with no pen position (start with M)", group, at);
        draw(Element::line(*pen_, Point(v[0], v[1])), group, at);
        return;
      case 'A': {
        if (!(v[2] > 0)) fail("radius must be positive", group, at);
        const double sweep = v[4] - v[3];
        if (sweep == 0 || std::abs(sweep) > 360) fail("sweep must be in (0, 360] degrees", group, at);
        draw(Element::arc(Point(v[0], v[1]), v[2], radians(v[3]), radians(sweep)), group, at);
        return;
      }
      case 'E': {
        if (!(v[2] > 0) || !(v[3] > 0)) fail("radii must be positive", group, at);
        const double sweep = v[5] - v[4];
        if (sweep == 0 || std::abs(sweep) > 360) fail("sweep must be in (0, 360] degrees", group, at);
        draw(Element::ellipse(Point(v[0], v[1]), v[2], v[3], 0.0, radians(v[4]), radians(sweep)),
             group, at);
        return;
      }
    }
  }

  // Appends a lit element, preceded by a laser-off move from the previous lit element when it
  // does not start where that one ended. A line written to a few decimals that nearly reaches the
  // start of the arc after it is snapped onto it, so scripts need no 10-digit coordinates.
  void draw(const Element& element, std::string_view group, std::size_t at) {
    if (element.length() < kMinLength) fail("zero-length element", group, at);
    const Point start = element.start();
    if (pen_) {
      const double gap = (start - *pen_).norm();
      if (pending_move_) {
        if (gap >= kSnapTol) fail("element does not start at the point of the preceding M", group, at);
      } else if (gap > kJoinTol && gap < kSnapTol) {
        if (glyph_.elements.empty() || glyph_.elements.back().kind() != ElementKind::line)
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
  std::optional<Point> pen_;
  std::optional<Point> last_lit_end_;
  bool pending_move_ = false;
  std::size_t pending_move_at_ = 0;
  std::size_t command_at_ = 0;
  bool had_group_ = false;
};

}  // namespace

Glyph parse_glyph_script(char32_t code_point, double advance, std::string_view script) {
  return ScriptParser(code_point, advance, script).parse();
}

}  // namespace mark
