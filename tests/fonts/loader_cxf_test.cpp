// QCAD .cxf loader: lines, counter-clockwise and clockwise arcs in degrees, full circles written
// with equal angles, the three glyph header styles, and malformed records with line numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/numbers.hpp"
#include "fonts/loaders.hpp"
#include "loader_test_util.hpp"

namespace mark {
namespace {

using test::expect_font_error;
using test::expect_point;

constexpr double kDeg = kPi / 180;

const StrokeFont& sample() {
  static const StrokeFont font = load_font_file(test::kDataDir + "/sample.cxf");
  return font;
}

const CircularArc& arc_of(const Element& e) {
  EXPECT_EQ(e.kind(), ElementKind::arc);
  return std::get<CircularArc>(e.geometry());
}

TEST(LoaderCxf, SampleFontAndMetrics) {
  Warnings w;
  const StrokeFont f = load_font_file(test::kDataDir + "/sample.cxf", &w);
  EXPECT_TRUE(w.empty());
  EXPECT_EQ(f.name(), "sample");
  EXPECT_EQ(f.size(), 10u);
  EXPECT_EQ(f.metrics().cap_height, 9);
  EXPECT_EQ(f.metrics().x_height, 6);
  EXPECT_EQ(f.metrics().descender, 0);
  EXPECT_NEAR(f.metrics().ascender, 10.85, 1e-12);  // the ring of Å
  EXPECT_DOUBLE_EQ(f.metrics().line_height, 14.4);
  EXPECT_EQ(f.metrics().word_spacing, 6.75);
}

TEST(LoaderCxf, HeaderStyles) {
  // [0041] A, [#0048], [O] 8 (old style: the character and its element count), [é] 2 (UTF-8).
  EXPECT_EQ(sample().glyph(U'A').advance, 9);  // rightmost x 6 + LetterSpacing 3
  EXPECT_EQ(sample().glyph(U'H').advance, 8);
  EXPECT_EQ(sample().glyph(U'O').advance, 8);
  EXPECT_EQ(test::count_lit(sample().glyph(U'x')), 2u);
  EXPECT_EQ(test::count_lit(sample().glyph(U'\u00E9')), 2u);
}

TEST(LoaderCxf, CounterClockwiseArcs) {
  // O: "A 2,7,2,90,180" is the top-left corner: centre (2,7), radius 2, from 90° to 180°. The
  // file draws it from (2,9) to (0,7); it is reversed so that O is one closed stroke.
  const Glyph& o = sample().glyph(U'O');
  ASSERT_EQ(o.elements.size(), 8u);
  EXPECT_EQ(test::count_travel(o), 0u);
  test::expect_continuous(o, 1e-12);
  const CircularArc& corner = arc_of(o.elements[1]);
  expect_point(corner.center, 2, 7);
  EXPECT_EQ(corner.radius, 2);
  expect_point(o.elements[1].start(), 0, 7);
  expect_point(o.elements[1].point_at(0.5), 2 - std::sqrt(2.0), 7 + std::sqrt(2.0));
  expect_point(o.elements[1].end(), 2, 9);
  EXPECT_NEAR(corner.sweep, -kPi / 2, 1e-12);  // reversed: clockwise from 180° to 90°
  expect_point(o.elements.back().end(), 0, 2);
}

TEST(LoaderCxf, ArcWrappingThroughZeroDegrees) {
  // 2: "A 3,7.149,1,329.8,20.53" runs counter-clockwise through 0°: 50.73°.
  const Glyph& two = sample().glyph(U'2');
  const Element* wrap = nullptr;
  for (const Element& e : two.elements)
    if (e.kind() == ElementKind::arc && arc_of(e).radius == 1) wrap = &e;
  ASSERT_NE(wrap, nullptr);
  EXPECT_NEAR(std::abs(arc_of(*wrap).sweep), 50.73 * kDeg, 1e-12);
  EXPECT_NEAR(wrap->length(), 50.73 * kDeg, 1e-12);
  // Whichever way the stroke runs, the arc passes through 0° at (4, 7.149).
  const double t0 = (arc_of(*wrap).sweep > 0 ? 30.2 : 20.53) / 50.73;
  expect_point(wrap->point_at(t0), 4, 7.149, 1e-12);
}

TEST(LoaderCxf, ClockwiseArc) {
  // Þ: "AR 2,4.5,1.5,90,270" — clockwise from 90° to 270°: the bowl on the right, through
  // (3.5,4.5).
  const Glyph& thorn = sample().glyph(U'\u00DE');
  ASSERT_EQ(thorn.elements.size(), 5u);
  EXPECT_EQ(test::count_travel(thorn), 0u);  // the pieces join into one path
  const CircularArc& bowl = arc_of(thorn.elements[3]);
  expect_point(bowl.center, 2, 4.5);
  EXPECT_EQ(bowl.radius, 1.5);
  EXPECT_NEAR(bowl.start_angle, kPi / 2, 1e-15);
  EXPECT_NEAR(bowl.sweep, -kPi, 1e-15);
  expect_point(thorn.elements[3].start(), 2, 6);
  expect_point(thorn.elements[3].point_at(0.5), 3.5, 4.5);
  expect_point(thorn.elements[3].end(), 2, 3);
  EXPECT_NEAR(thorn.bounds().max.x(), 3.5, 1e-12);
  EXPECT_NEAR(thorn.advance, 6.5, 1e-12);
}

TEST(LoaderCxf, EqualAnglesAreAFullCircle) {
  // ©: "A 4.5,4.5,4.5,180,180"; Å: "A 3,10.5,0.35,0,360".
  const Glyph& copyright = sample().glyph(U'\u00A9');
  const CircularArc& ring = arc_of(copyright.elements.front());
  EXPECT_NEAR(std::abs(ring.sweep), 2 * kPi, 1e-15);
  EXPECT_NEAR(copyright.elements.front().length(), 9 * kPi, 1e-12);
  expect_point(copyright.elements.front().start(), 0, 4.5);
  expect_point(copyright.elements.front().end(), 0, 4.5);
  const Box b = copyright.bounds();
  expect_point(b.min, 0, 0);
  expect_point(b.max, 9, 9);
  EXPECT_EQ(copyright.advance, 12);

  const Glyph& ring_a = sample().glyph(U'\u00C5');
  const Element& small = ring_a.elements.back();
  EXPECT_NEAR(arc_of(small).sweep, 2 * kPi, 1e-15);
  EXPECT_NEAR(small.length(), 0.7 * kPi, 1e-12);
}

TEST(LoaderCxf, TwoSemicirclesMakeOneClosedStroke) {
  const Glyph& degree = sample().glyph(U'\u00B0');
  ASSERT_EQ(degree.elements.size(), 2u);
  EXPECT_TRUE(degree.elements[0].laser() && degree.elements[1].laser());
  expect_point(degree.elements[0].point_at(0.5), 0, 7.5);
  expect_point(degree.elements[1].point_at(0.5), 3, 7.5);
}

TEST(LoaderCxf, OldStyleLiteralHeaders) {
  Warnings w;
  const StrokeFont f = parse_cxf(
      "[]] 1\nL 0,0,1,0\n\n[[] 1\nL 0,0,1,0\n\n[#] 1\nL 0,0,1,0\n\n[A] 3\nL 0,0,1,0\n"
      "[B]\nL 0,0,1,0\n[0043] C\nL 0,0,1,0\n",
      "old.cxf", &w);
  for (char32_t cp : {U']', U'[', U'#', U'A', U'B', U'C'})
    EXPECT_NE(f.find(cp), nullptr) << char(cp);
  ASSERT_EQ(w.size(), 1u);  // a body may end at the next header, without a blank line
  EXPECT_EQ(w[0], "old.cxf:10: glyph 'A' (U+0041) declares 3 elements but has 1");
}

TEST(LoaderCxf, Latin1Encoding) {
  const StrokeFont f = parse_cxf(
      "# Encoding: ISO-8859-1\n[\xe9] 1\nL 0,0,1,1\n\n[00FC] \xfc\nL 0,0,2,2\n", "l1.cxf");
  EXPECT_NE(f.find(U'\u00E9'), nullptr);
  EXPECT_NE(f.find(U'\u00FC'), nullptr);
}

TEST(LoaderCxf, ZeroLengthRecordsAreDropped) {
  // ttf2cxf output repeats points ("L a,b,a,b"); they draw nothing.
  const StrokeFont f = parse_cxf("[#0041]\nL 0,0,1,1\nL 1,1,1,1\nL 1,1,2,0\n", "z.cxf");
  EXPECT_EQ(f.glyph(U'A').elements.size(), 2u);
}

TEST(LoaderCxf, MalformedFilesNameTheLine) {
  const std::string s = "bad.cxf";
  const auto fails = [&](const std::string& text, std::size_t line, std::string_view what) {
    SCOPED_TRACE(text);
    expect_font_error([&] { parse_cxf(text, s); }, s, line, what);
  };
  const std::string ok = "[0041] A\nL 0,0,1,1\n\n";
  fails(ok + "[0042] B\nX 1,2,3,4\n", 5, "unknown record 'X 1,2,3,4' (expected L, A or AR)");
  fails(ok + "[0042] B\nl 1,2,3,4\n", 5, "unknown record");
  fails(ok + "[0042] B\nARC 1,2,3,4,5\n", 5, "unknown record");
  fails(ok + "[0042] B\nL 1,2,3\n", 5, "L record 'L 1,2,3' needs 4 numbers, found 3");
  fails(ok + "[0042] B\nL 1,2,3,4,5\n", 5, "needs 4 numbers, found 5");
  fails(ok + "[0042] B\nA 1,2,3,4\n", 5, "A record 'A 1,2,3,4' needs 5 numbers, found 4");
  fails(ok + "[0042] B\nAR\n", 5, "needs 5 numbers");
  fails(ok + "[0042] B\nL 1,a,3,4\n", 5, "value 'a' is not a number");
  fails(ok + "[0042] B\nL 1,,3,4\n", 5, "value '' is not a number");
  fails(ok + "[0042] B\nA 0,0,0,0,90\n", 5, "arc 'A 0,0,0,0,90' has a non-positive radius");
  fails(ok + "[0042] B\nAR 0,0,-1,0,90\n", 5, "non-positive radius");
  fails(ok + "[0042] B\nL 0,0,nan,1\n", 5, "value 'nan' is not finite");
  fails(ok + "[0042] B\nA 0,0,1,inf,90\n", 5, "is not finite");
  fails(ok + "[0042] B\nL 0,0,1e9,1\n", 5, "is out of range");
  fails(ok + "[0042] B\nL 0,0,1e999,1\n", 5, "is out of range");
  fails(ok + "[GG] B\nL 0,0,1,1\n", 4, "bad glyph header '[GG] B'");
  fails(ok + "[A] x\nL 0,0,1,1\n", 4, "bad element count 'x'");
  fails(ok + "[#12345678]\n", 4, "bad glyph header");
  fails("# LetterSpacing: 3,5\n" + ok, 1, "LetterSpacing '3,5' is not a number");
  fails(ok + std::string("[0042] B\nL 0,0,1,1\x1a\n"), 5, "control byte 0x1A");
  fails(ok + "[0042] \xc3\x28\n", 4, "invalid UTF-8");
  fails("# Format: QCad II Font\n\n", 2, "no glyphs");
}

}  // namespace
}  // namespace mark
