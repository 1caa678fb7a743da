// The G-code writer on hand-made toolpaths: numbers always with a decimal point, I/J from the
// rounded end points with the radius error far under 0.005 mm, arcs that round to nothing
// dropped (never a full circle), subprogram structure per dialect, user header and footer.
#include "marker/cnc/gcode_writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <regex>
#include <sstream>

#include "base/error.hpp"
#include "marker/cnc/gcode_number.hpp"
#include "rs274.hpp"

namespace mark {
namespace {

Toolpath arc_letter() {
  Toolpath tp;
  ToolSubprogram sub;
  sub.label = "'(' (U+0028)";  // parentheses must not break the comment
  sub.body.push_back(ToolMove::rapid(1, 0, 5));
  sub.body.push_back(ToolMove::feed(1, 0, -0.1, 100));
  // A third of a circle of radius 1.234567 about (0.2, 0.3), end point not on the 0.1 µm grid.
  const Point c(0.2, 0.3);
  const double r = 1.234567;
  const Point s = c + r * Point(std::cos(0.1), std::sin(0.1));
  sub.body.push_back(ToolMove::feed(s.x(), s.y(), -0.1, 300));
  const Point e = c + r * Point(std::cos(0.1 + 2.0), std::sin(0.1 + 2.0));
  sub.body.push_back(ToolMove::arc(e.x(), e.y(), -0.1, c, true, 300));
  // An arc so small it rounds to nothing.
  sub.body.push_back(ToolMove::arc(e.x() + 1e-6, e.y(), -0.1, e + Point(0.5e-6, 0.3), true, 300));
  sub.body.push_back(ToolMove::rapid(e.x(), e.y(), 5));
  tp.subs.push_back(sub);
  tp.steps.push_back(SubprogramCall{0, Point(10, 20), 0});
  tp.steps.push_back(SubprogramCall{0, Point(-10, 5), std::numbers::pi / 6});
  return tp;
}

TEST(GcodeNumber, AlwaysADecimalPointNeverMinusZero) {
  EXPECT_EQ(format_number(10, 4), "10.");
  EXPECT_EQ(format_number(-0.00001, 4), "0.");
  EXPECT_EQ(format_number(1.23456, 4), "1.2346");
  EXPECT_EQ(format_number(-2.5, 3), "-2.5");
  EXPECT_EQ(format_number(12000, 0), "12000.");
}

TEST(GcodeWriter, EveryNumberHasADecimalPoint) {
  for (Dialect d : {Dialect::linuxcnc, Dialect::fanuc, Dialect::plain}) {
    GcodeOptions o;
    o.dialect = d;
    const std::string g = write_gcode(arc_letter(), o);
    std::istringstream in(g);
    std::string line;
    const std::regex word(R"(\b([XYZIJF])(-?[0-9.]+))");
    while (std::getline(in, line)) {
      if (line.front() == '(') continue;
      for (auto it = std::sregex_iterator(line.begin(), line.end(), word); it != std::sregex_iterator(); ++it)
        EXPECT_NE((*it)[2].str().find('.'), std::string::npos) << line;
    }
  }
}

TEST(GcodeWriter, ArcCentresFromRoundedEndPoints) {
  GcodeStats st;
  GcodeOptions o;
  o.dialect = Dialect::plain;
  const std::string g = write_gcode(arc_letter(), o, &st);
  EXPECT_EQ(st.arcs, 2u);  // one real arc per occurrence; the tiny one is gone
  EXPECT_LE(st.max_arc_radius_error_mm, 0.0002);
  // Every G2/G3 reproduces its radius from the printed numbers.
  std::istringstream in(g);
  std::string line;
  double x = 0, y = 0;
  const std::regex xy(R"(X(-?[0-9.]+) Y(-?[0-9.]+))"), ij(R"(I(-?[0-9.]+) J(-?[0-9.]+))");
  while (std::getline(in, line)) {
    std::smatch m, n;
    if (!std::regex_search(line, m, xy)) continue;
    const double ex = std::stod(m[1]), ey = std::stod(m[2]);
    if (line.rfind("G3", 0) == 0 || line.rfind("G2", 0) == 0) {
      ASSERT_TRUE(std::regex_search(line, n, ij));
      const double cx = x + std::stod(n[1]), cy = y + std::stod(n[2]);
      EXPECT_NEAR(std::hypot(ex - cx, ey - cy), std::hypot(x - cx, y - cy), 0.0002) << line;
      EXPECT_NEAR(std::hypot(x - cx, y - cy), 1.234567, 0.0002) << line;
    }
    x = ex, y = ey;
  }
}

TEST(GcodeWriter, DialectStructure) {
  REQUIRE_RS274();
  GcodeOptions o;
  o.header = {"G64 P0.01"};
  o.footer = {"(done)"};
  o.title = "test (1)";
  o.dialect = Dialect::linuxcnc;
  const std::string lc = write_gcode(arc_letter(), o);
  EXPECT_EQ(lc.rfind("(test [1])\nG17 G21 G40 G90 G91.1 G94\nG64 P0.01\no<ch0> sub\n", 0), 0u) << lc;
  EXPECT_NE(lc.find("o<ch0> call [10.] [20.] [0.]\n"), std::string::npos);
  EXPECT_NE(lc.find("o<ch0> call [-10.] [5.] [30.]\n"), std::string::npos);
  EXPECT_NE(lc.find("COS[#3]"), std::string::npos);
  EXPECT_NE(lc.find("(done)\nM30\n"), std::string::npos);

  o.dialect = Dialect::fanuc;
  o.end_with_m30 = false;
  const std::string fa = write_gcode(arc_letter(), o);
  EXPECT_EQ(fa.rfind("%\nO0001 (TEST [1])\n", 0), 0u) << fa;
  EXPECT_NE(fa.find("G52 X10. Y20.\nM98 P1001\n"), std::string::npos);
  EXPECT_NE(fa.find("S10000 M3"), std::string::npos);  // integer spindle speed on Fanuc
  EXPECT_NE(fa.find("M2\nO1001 ("), std::string::npos);  // subprogram after the end
  EXPECT_NE(fa.find("M99\n%\n"), std::string::npos);
  EXPECT_EQ(fa.find('#'), std::string::npos);  // the rotated occurrence is inlined, no macros

  o.dialect = Dialect::plain;
  const std::string pl = write_gcode(arc_letter(), o);
  EXPECT_EQ(pl.find("G91.1"), std::string::npos);
  EXPECT_EQ(pl.find("G90.1"), std::string::npos);
  EXPECT_EQ(pl.find("o<"), std::string::npos);
  EXPECT_EQ(pl.find("M98"), std::string::npos);
  EXPECT_NE(pl.find("S10000. M3"), std::string::npos);
  for (Dialect d : {Dialect::linuxcnc, Dialect::fanuc, Dialect::plain}) {
    o.dialect = d;
    const test::Rs274Run run = test::run_rs274(write_gcode(arc_letter(), o), std::string("writer_") + std::to_string(static_cast<int>(d)));
    EXPECT_EQ(run.exit_code, 0) << run.errors;
  }
}

TEST(GcodeWriter, RefusesLinesThatWouldEndTheProgram) {
  GcodeOptions o;
  o.header = {"G0 X0\nM2"};
  EXPECT_THROW(write_gcode(arc_letter(), o), InputError);
  o.header = {"%"};
  EXPECT_THROW(write_gcode(arc_letter(), o), InputError);
  o.header.clear();
  o.program_number = 10000;
  EXPECT_THROW(write_gcode(arc_letter(), o), InputError);
}

// The LinuxCNC limit is measured, not assumed: rs274 reads a 252-character line and refuses one of
// 253 with "Command too long".
TEST(GcodeWriter, LinuxcncLineLimitIsWhatRs274Accepts) {
  REQUIRE_RS274();
  const std::size_t limit = dialect_limits(Dialect::linuxcnc).line_chars;
  auto program = [](std::size_t chars) {
    return "(" + std::string(chars - 2, 'A') + ")\nG21 G90 G0 X1. Y2.\nM2\n";
  };
  const test::Rs274Run fits = test::run_rs274(program(limit), "line_limit_fits");
  EXPECT_EQ(fits.exit_code, 0) << fits.errors;
  const test::Rs274Run too_long = test::run_rs274(program(limit + 1), "line_limit_too_long");
  EXPECT_NE(too_long.exit_code, 0);
  EXPECT_NE(too_long.errors.find("Command too long"), std::string::npos) << too_long.errors;
}

// A long title wraps into comment lines within every dialect's limit, keeps every character,
// one comment per line of the title, and the programs still run.
TEST(GcodeWriter, LongTitlesWrapWithinEachDialectsLines) {
  REQUIRE_RS274();
  std::string title;
  for (int k = 0; k < 40; ++k) {
    if (k) title += '\n';
    title += "LINE " + std::to_string(k) + " ";
    title.append(90, 'W');
  }
  title += "\n" + std::string(600, 'Z');  // one word longer than any line
  GcodeOptions o;
  o.title = title;
  for (Dialect d : {Dialect::linuxcnc, Dialect::fanuc, Dialect::plain}) {
    o.dialect = d;
    const DialectLimits limits = dialect_limits(d);
    const std::string program = write_gcode(arc_letter(), o);
    std::istringstream in(program);
    std::string line, comments;
    std::size_t n = 0;
    while (std::getline(in, line)) {
      EXPECT_LE(line.size(), limits.line_chars) << to_string(d) << " line " << n;
      if (d == Dialect::fanuc && n == 1) {
        EXPECT_EQ(line.rfind("O0001 (", 0), 0u) << line;
        EXPECT_LE(line.size() - 7 - 1, limits.program_name_chars) << line;
        line = line.substr(6);
      }
      if (line.size() > 2 && line.front() == '(' && line.find_first_of("LWZ") == 1)
        comments += line.substr(1, line.size() - 2);
      ++n;
    }
    // Every character survives (a wrap drops only the space it breaks at).
    for (int k = 0; k < 40; ++k)
      EXPECT_NE(comments.find("LINE " + std::to_string(k)), std::string::npos) << to_string(d) << " " << k;
    EXPECT_EQ(std::count(comments.begin(), comments.end(), 'W'), 40 * 90) << to_string(d);
    EXPECT_EQ(std::count(comments.begin(), comments.end(), 'Z'), 600) << to_string(d);
    const test::Rs274Run run = test::run_rs274(program, "long_title_" + std::string(to_string(d)));
    EXPECT_EQ(run.exit_code, 0) << to_string(d) << ": " << run.errors;
  }
}

TEST(GcodeWriter, RefusesUserLinesLongerThanTheDialectsLimit) {
  GcodeOptions o;
  o.dialect = Dialect::plain;
  o.header = {std::string(79, 'G')};
  EXPECT_NO_THROW(write_gcode(arc_letter(), o));
  o.header = {std::string(80, 'G')};
  try {
    write_gcode(arc_letter(), o);
    FAIL() << "an 80-character grbl line was written";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "header line 'GGGGGGGGGGGGGGGGGGGG…' has 80 characters, more than the plain dialect's 79 per line");
  }
  o.dialect = Dialect::linuxcnc;
  EXPECT_NO_THROW(write_gcode(arc_letter(), o));
  o.footer = {std::string(253, 'G')};
  EXPECT_THROW(write_gcode(arc_letter(), o), InputError);
}

}  // namespace
}  // namespace mark
