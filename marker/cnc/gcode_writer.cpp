#include "marker/cnc/gcode_writer.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "base/error.hpp"
#include "fonts/overloaded.hpp"
#include "marker/cnc/gcode_number.hpp"

namespace mark {
namespace {

constexpr double kMmPerInch = 25.4;
constexpr double kMaxRadiusErrorMm = 0.005;  // what grbl and Beckhoff accept without a relative test
constexpr int kAngleDecimals = 6;            // degrees; 1e-6° moves a point 50 mm out by 1 nm
constexpr double kRotated = 1e-12;           // radians below which a call counts as unrotated

// How subprogram coordinates reach the machine: literal numbers (main program, inlined code,
// Fanuc subprograms placed by G52), shifted by the call's #1/#2, or also rotated by #3.
enum class Frame { literal, shifted, rotated };

// A comment's text the controller will not choke on: printable ASCII without parentheses.
std::string comment_text(const std::string& text, bool upper) {
  std::string c;
  for (unsigned char ch : text) {
    char o = ch >= 0x20 && ch < 0x7F ? static_cast<char>(ch) : '?';
    if (o == '(') o = '[';
    if (o == ')') o = ']';
    if (upper) o = static_cast<char>(std::toupper(static_cast<unsigned char>(o)));
    c += o;
  }
  return c;
}

std::string parenthesised(std::string_view text) {
  std::string c;
  c.reserve(text.size() + 2);
  c += '(';
  c += text;
  c += ')';
  return c;
}

std::string comment(const std::string& text, bool upper) { return parenthesised(comment_text(text, upper)); }

// The text as comments of at most `width` characters each (parentheses included; the first at
// most `first_width`): one per line of the text, long lines wrapped at a space where there is
// one, nothing dropped.
std::vector<std::string> comment_lines(const std::string& text, bool upper, std::size_t width,
                                       std::size_t first_width) {
  std::vector<std::string> out;
  auto room = [&] { return (out.empty() ? first_width : width) - 2; };
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line = comment_text(text.substr(start, end - start), upper);
    while (line.size() > room()) {
      std::size_t cut = line.rfind(' ', room());
      if (cut == std::string::npos || cut == 0) cut = room();
      out.push_back(parenthesised(std::string_view(line).substr(0, cut)));
      line.erase(0, line[cut] == ' ' ? cut + 1 : cut);
    }
    out.push_back(parenthesised(line));
    start = end + 1;
  }
  return out;
}

class Writer {
 public:
  Writer(const Toolpath& tp, const GcodeOptions& o, const Progress& progress) : tp_(tp), o_(o), progress_(progress) {
    const bool inch = o.units == Units::inch;
    dec_ = inch ? 5 : 4;
    feed_dec_ = inch ? 2 : 1;
    scale_ = inch ? 1 / kMmPerInch : 1.0;
    rotated_sub_.assign(tp.subs.size(), false);
    called_sub_.assign(tp.subs.size(), false);
    for (const ToolStep& st : tp.steps)
      if (const auto* c = std::get_if<SubprogramCall>(&st)) {
        const bool rot = std::abs(c->rotation_rad) > kRotated;
        rotated_sub_[c->sub] = rotated_sub_[c->sub] || rot;
        // Fanuc calls only the unrotated occurrences (G52 shifts, it cannot rotate).
        if (o.dialect == Dialect::linuxcnc || (o.dialect == Dialect::fanuc && !rot))
          called_sub_[c->sub] = true;
      }
  }

  std::string run(GcodeStats* stats) {
    switch (o_.dialect) {
      case Dialect::linuxcnc: linuxcnc(); break;
      case Dialect::fanuc: fanuc(); break;
      case Dialect::plain: plain(); break;
    }
    if (stats) *stats = stats_;
    return std::move(out_);
  }

 private:
  const Toolpath& tp_;
  const GcodeOptions& o_;
  const Progress& progress_;
  const DialectLimits limits_ = dialect_limits(o_.dialect);
  int dec_ = 4, feed_dec_ = 1;
  double scale_ = 1;
  std::vector<bool> rotated_sub_, called_sub_;
  std::string out_;
  GcodeStats stats_;
  // Modal state as the controller sees it, in the current frame and output units (rounded).
  std::optional<Eigen::Vector3d> pos_;
  std::optional<double> feed_;
  Frame frame_ = Frame::literal;

  bool upper() const { return o_.dialect == Dialect::fanuc; }
  bool uses_comp() const {
    for (const ToolStep& st : tp_.steps)
      if (const auto* m = std::get_if<ToolMove>(&st); m && m->comp != CompSide::unchanged) return true;
    return false;
  }
  void line(const std::string& s) {
    // Every line the writer makes is far shorter; this guards the limit against a future change.
    if (s.size() > limits_.line_chars)
      throw std::logic_error("G-code writer: line " + std::to_string(stats_.lines + 1) + " has " +
                             std::to_string(s.size()) + " characters, more than the " +
                             std::string(to_string(o_.dialect)) + " limit of " +
                             std::to_string(limits_.line_chars));
    out_ += s;
    out_ += '\n';
    if (++stats_.lines % 4096 == 0) progress_.step("gcode: writing lines", stats_.lines, 0);
  }
  void forget() {
    pos_.reset();
    feed_.reset();
  }
  std::string num(double v) const { return format_number(v, dec_); }
  double round_units(double mm) const { return round_to(mm * scale_, dec_); }

  std::string units_word() const { return o_.units == Units::inch ? "G20" : "G21"; }

  // ---- program frame -------------------------------------------------------------------------
  // Plane, units, no cutter compensation, absolute coordinates, then the dialect's extras.
  void preamble(const std::string& extra) {
    line("G17 " + units_word() + " G40 G90" + extra);
    for (const std::string& h : o_.header) line(h);
  }
  void start_spindle(bool integer_speed) {
    line("G0 Z" + num(tp_.safe_z_mm * scale_));
    pos_.reset();
    if (o_.spindle_rpm > 0) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.0f", o_.spindle_rpm);
      line(std::string("S") + buf + (integer_speed ? "" : ".") + " M3");
    }
  }
  void finish() {
    // Back to safe height wherever the last step left the tool.
    if (!pos_ || pos_->z() != round_units(tp_.safe_z_mm)) line("G0 Z" + num(tp_.safe_z_mm * scale_));
    if (o_.spindle_rpm > 0) line("M5");
    for (const std::string& f : o_.footer) line(f);
    line(o_.end_with_m30 ? "M30" : "M2");
  }
  void title() {
    if (o_.title.empty()) return;
    for (const std::string& c : comment_lines(o_.title, upper(), limits_.line_chars, limits_.line_chars))
      line(c);
  }

  // ---- dialects ------------------------------------------------------------------------------
  std::string sub_name(std::size_t k) const { return "o<ch" + std::to_string(k) + ">"; }

  void linuxcnc() {
    title();
    // G91.1: arc centres relative to the start (LinuxCNC's default, made explicit).
    preamble(" G91.1 G94");
    // Definitions come first: LinuxCNC must have read a subprogram before it is called.
    for (std::size_t k = 0; k < tp_.subs.size(); ++k) {
      if (!called_sub_[k]) continue;
      line(sub_name(k) + " sub");
      line(comment(tp_.subs[k].label, false));
      frame_ = rotated_sub_[k] ? Frame::rotated : Frame::shifted;
      forget();
      for (const ToolMove& m : tp_.subs[k].body) move(m);
      line(sub_name(k) + " endsub");
    }
    frame_ = Frame::literal;
    forget();
    start_spindle(false);
    for (const ToolStep& st : tp_.steps)
      std::visit(Overloaded{[&](const ToolMove& m) { move(m); },
                            [&](const SubprogramCall& c) {
                              std::string s = sub_name(c.sub) + " call [" + num(c.origin.x() * scale_) +
                                              "] [" + num(c.origin.y() * scale_) + "]";
                              if (rotated_sub_[c.sub])
                                s += " [" + format_number(c.rotation_rad * 180 / std::numbers::pi, kAngleDecimals) + "]";
                              line(s);
                              ++stats_.calls;
                              forget();
                            }},
                 st);
    finish();
  }

  void fanuc() {
    line("%");
    char head[16];
    std::snprintf(head, sizeof head, "O%04d", o_.program_number);
    std::string first(head);
    // The program name on the O line; a longer title continues in comment lines below it.
    std::vector<std::string> name;
    if (!o_.title.empty())
      name = comment_lines(o_.title, true, limits_.line_chars, limits_.program_name_chars + 2);
    if (!name.empty()) first.append(" ").append(name.front());
    line(first);
    for (std::size_t k = 1; k < name.size(); ++k) line(name[k]);
    preamble(" G94");
    if (uses_comp())
      line(comment("D1 = tool radius " + num(tp_.comp_diameter_mm / 2 * scale_) +
                       (o_.units == Units::inch ? " inch" : " mm") + " for G41",
                   true));
    start_spindle(true);  // Fanuc reads S as an integer
    bool shifted = false;
    for (const ToolStep& st : tp_.steps)
      std::visit(Overloaded{[&](const ToolMove& m) {
                              if (shifted) unshift(shifted);
                              move(m);
                            },
                            [&](const SubprogramCall& c) {
                              if (std::abs(c.rotation_rad) > kRotated) {
                                if (shifted) unshift(shifted);
                                inline_call(c);
                                return;
                              }
                              line("G52 X" + num(c.origin.x() * scale_) + " Y" + num(c.origin.y() * scale_));
                              line("M98 P" + std::to_string(o_.first_subprogram_number + static_cast<int>(c.sub)));
                              shifted = true;
                              ++stats_.calls;
                              forget();
                            }},
                 st);
    if (shifted) unshift(shifted);
    finish();
    // Subprograms after the end of the main program, where LinuxCNC looks for Fanuc-style subs.
    frame_ = Frame::literal;
    for (std::size_t k = 0; k < tp_.subs.size(); ++k) {
      if (!called_sub_[k]) continue;
      char number[16];
      std::snprintf(number, sizeof number, "O%d ", o_.first_subprogram_number + static_cast<int>(k));
      std::string head(number);
      head += comment(tp_.subs[k].label, true);
      line(head);
      forget();
      for (const ToolMove& m : tp_.subs[k].body) move(m);
      line("M99");
    }
    line("%");
  }

  void unshift(bool& shifted) {
    line("G52 X0. Y0.");
    shifted = false;
    forget();
  }

  void plain() {
    title();
    preamble(" G94");
    start_spindle(false);
    for (const ToolStep& st : tp_.steps)
      std::visit(Overloaded{[&](const ToolMove& m) { move(m); },
                            [&](const SubprogramCall& c) { inline_call(c); }},
                 st);
    finish();
  }

  void inline_call(const SubprogramCall& c) {
    line(comment(tp_.subs[c.sub].label, upper()));
    for (const ToolMove& m : tp_.subs[c.sub].body) move(place_move(m, c));
    ++stats_.inlined;
  }

  // ---- words ---------------------------------------------------------------------------------
  // " + c*factor" with the sign folded in; nothing when c rounds to zero.
  void term(std::string& s, double c, const char* factor, bool& first) const {
    const double r = round_to(c, dec_);
    if (r == 0) return;
    if (r < 0)
      s += '-';
    else if (!first)
      s += '+';
    s += num(std::abs(r));
    if (factor) (s += '*') += factor;
    first = false;
  }

  void append_xy(std::string& s, double x, double y) const {
    switch (frame_) {
      case Frame::literal:
        s += " X" + num(x) + " Y" + num(y);
        return;
      case Frame::shifted: {
        bool f = false;
        s += " X[#1";
        term(s, x, nullptr, f);
        s += "] Y[#2";
        f = false;
        term(s, y, nullptr, f);
        s += "]";
        return;
      }
      case Frame::rotated: {
        bool f = false;
        s += " X[#1";
        term(s, x, "COS[#3]", f);
        term(s, -y, "SIN[#3]", f);
        s += "] Y[#2";
        f = false;
        term(s, x, "SIN[#3]", f);
        term(s, y, "COS[#3]", f);
        s += "]";
        return;
      }
    }
  }

  void append_ij(std::string& s, double i, double j) const {
    if (frame_ != Frame::rotated) {
      s += " I" + num(i) + " J" + num(j);
      return;
    }
    auto rotated = [&](const char* word, double a, const char* fa, double b, const char* fb) {
      std::string e;
      bool f = true;
      term(e, a, fa, f);
      term(e, b, fb, f);
      s += std::string(" ") + word + (f ? "0." : "[" + e + "]");
    };
    rotated("I", i, "COS[#3]", -j, "SIN[#3]");
    rotated("J", i, "SIN[#3]", j, "COS[#3]");
  }

  void append_feed(std::string& s, double feed_mm_min) {
    const double f = round_to(feed_mm_min * scale_, feed_dec_);
    if (feed_ && *feed_ == f) return;
    s += " F" + format_number(f, feed_dec_);
    feed_ = f;
  }

  std::string comp_word(CompSide side) const {
    if (side == CompSide::cancel) return "G40 ";
    if (o_.dialect == Dialect::plain)
      throw InputError("cutter compensation (G41/G42) needs the linuxcnc or fanuc dialect: grbl has none");
    const bool left = side == CompSide::left;
    if (o_.dialect == Dialect::linuxcnc)  // G41.1/G42.1 take the diameter itself
      return std::string(left ? "G41.1" : "G42.1") + " D" + num(tp_.comp_diameter_mm * scale_) + " ";
    return std::string(left ? "G41" : "G42") + " D1 ";  // Fanuc: offset register 1 holds the radius
  }

  void move(const ToolMove& m) {
    const Eigen::Vector3d t(round_units(m.end.x()), round_units(m.end.y()), round_units(m.end.z()));
    const bool xy = !pos_ || pos_->x() != t.x() || pos_->y() != t.y();
    const bool z = !pos_ || pos_->z() != t.z();
    const bool comp = m.comp != CompSide::unchanged;
    std::string s = comp ? comp_word(m.comp) : std::string();
    switch (m.kind) {
      case MoveKind::rapid:
      case MoveKind::feed: {
        if (!xy && !z && !comp) return;
        const bool rapid = m.kind == MoveKind::rapid;
        s += rapid ? "G0" : "G1";
        if (xy || comp) append_xy(s, t.x(), t.y());
        if (z) s += " Z" + num(t.z());
        if (!rapid) append_feed(s, m.feed_mm_min);
        ++(rapid ? stats_.rapids : stats_.feeds);
        break;
      }
      case MoveKind::arc: {
        if (!pos_) throw std::logic_error("G-code writer: arc without a known start point");
        if (z) throw std::logic_error("G-code writer: arcs must stay at one height");
        if (!xy && !comp) return;  // rounds to nothing: never let it become a full circle
        const Eigen::Vector2d a(pos_->x(), pos_->y()), b(t.x(), t.y());
        // The exact centre moved onto the bisector of the rounded chord, then I/J rounded.
        Eigen::Vector2d c = m.center * scale_;
        const Eigen::Vector2d chord = b - a;
        if (chord.norm() > 0) {
          const Eigen::Vector2d u(-chord.y() / chord.norm(), chord.x() / chord.norm());
          const Eigen::Vector2d mid = (a + b) / 2;
          c = mid + (c - mid).dot(u) * u;
        }
        const double i = round_to(c.x() - a.x(), dec_), j = round_to(c.y() - a.y(), dec_);
        const Eigen::Vector2d cc = a + Eigen::Vector2d(i, j);
        const double err_mm = std::abs((b - cc).norm() - (a - cc).norm()) / scale_;
        if (err_mm > kMaxRadiusErrorMm) {
          // Cannot happen for arcs the arc spline lets through (radius ≫ rounding); a line is
          // the safe way out should it ever.
          s += "G1";
          append_xy(s, t.x(), t.y());
          append_feed(s, m.feed_mm_min);
          ++stats_.feeds;
          break;
        }
        stats_.max_arc_radius_error_mm = std::max(stats_.max_arc_radius_error_mm, err_mm);
        s += m.ccw ? "G3" : "G2";
        append_xy(s, t.x(), t.y());
        append_ij(s, i, j);
        append_feed(s, m.feed_mm_min);
        ++stats_.arcs;
        break;
      }
    }
    line(s);
    pos_ = t;
  }
};

}  // namespace

void validate(const GcodeOptions& o) {
  const DialectLimits limits = dialect_limits(o.dialect);
  auto check = [&](const std::vector<std::string>& lines, const char* what) {
    for (const std::string& l : lines) {
      if (l.find_first_of("\r\n%") != std::string::npos)
        throw InputError(std::string(what) + " line '" + l +
                         "' contains a line break or '%', which would end the program early");
      if (l.size() > limits.line_chars)
        throw InputError(std::string(what) + " line '" + l.substr(0, 20) + "…' has " +
                         std::to_string(l.size()) + " characters, more than the " +
                         std::string(to_string(o.dialect)) + " dialect's " +
                         std::to_string(limits.line_chars) + " per line");
    }
  };
  check(o.header, "header");
  check(o.footer, "footer");
  if (o.program_number < 1 || o.program_number > 9999)
    throw InputError("program number O" + std::to_string(o.program_number) + " is outside O1..O9999");
  if (o.first_subprogram_number < 1 || o.first_subprogram_number > 9999)
    throw InputError("subprogram number O" + std::to_string(o.first_subprogram_number) +
                     " is outside O1..O9999");
  if (!(o.spindle_rpm >= 0) || !std::isfinite(o.spindle_rpm))
    throw InputError("spindle speed must be 0 (off) or positive");
}

std::string write_gcode(const Toolpath& toolpath, const GcodeOptions& options, GcodeStats* stats,
                        const Progress& progress) {
  validate(options);
  if (options.dialect == Dialect::fanuc &&
      options.first_subprogram_number + static_cast<long>(toolpath.subs.size()) > 10000)
    throw InputError("too many subprograms for Fanuc O numbers from O" +
                     std::to_string(options.first_subprogram_number));
  return Writer(toolpath, options, progress).run(stats);
}

DialectLimits dialect_limits(Dialect d) {
  switch (d) {
    case Dialect::linuxcnc: return {252, 0};
    case Dialect::fanuc: return {128, 31};
    case Dialect::plain: return {79, 0};
  }
  return {79, 0};
}

std::string_view to_string(Dialect d) {
  switch (d) {
    case Dialect::linuxcnc: return "linuxcnc";
    case Dialect::fanuc: return "fanuc";
    case Dialect::plain: return "plain";
  }
  return "plain";
}

Dialect parse_dialect(const std::string& name) {
  if (name == "linuxcnc") return Dialect::linuxcnc;
  if (name == "fanuc") return Dialect::fanuc;
  if (name == "plain" || name == "grbl") return Dialect::plain;
  throw InputError("unknown G-code dialect '" + name + "' (linuxcnc, fanuc or plain)");
}

Units parse_units(const std::string& name) {
  if (name == "mm") return Units::mm;
  if (name == "inch" || name == "in") return Units::inch;
  throw InputError("unknown units '" + name + "' (mm or inch)");
}

}  // namespace mark
