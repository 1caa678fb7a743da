// The G-code writer on hand-made toolpaths: numbers always with a decimal point, I/J from the
// rounded end points with the radius error far under 0.005 mm, arcs that round to nothing
// dropped (never a full circle), subprogram structure per dialect, user header and footer.
#include "marker/cnc/gcode_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <regex>
#include <sstream>

#include "fonts/error.hpp"
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

}  // namespace
}  // namespace mark
