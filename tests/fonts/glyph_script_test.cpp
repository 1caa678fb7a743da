// The glyph drawing language of the built-in font: exact elements, automatic moves, joins, and
// errors that name the glyph and the offending token.
#include "fonts/builtin/glyph_script.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "tests/fonts/loader_test_util.hpp"

namespace mark {
namespace {

using ::testing::HasSubstr;

using test::expect_point;  // tests/fonts/loader_test_util.hpp, within 1e-12

TEST(GlyphScript, LinesAndAnAutomaticMove) {
  const Glyph g = parse_glyph_script(U'A', 9, "M1,0 L4.5,10 8,0 M6.95,3 L2.05,3");
  EXPECT_EQ(g.code_point, U'A');
  EXPECT_EQ(g.advance, 9);
  ASSERT_EQ(g.elements.size(), 4u);
  EXPECT_TRUE(g.elements[0].laser());
  expect_point(g.elements[0].start(), 1, 0);
  expect_point(g.elements[0].end(), 4.5, 10);
  expect_point(g.elements[1].end(), 8, 0);
  EXPECT_FALSE(g.elements[2].laser());
  EXPECT_EQ(g.elements[2].kind(), ElementKind::line);
  expect_point(g.elements[2].start(), 8, 0);
  expect_point(g.elements[2].end(), 6.95, 3);
  EXPECT_TRUE(g.elements[3].laser());
  expect_point(g.elements[3].end(), 2.05, 3);
}

TEST(GlyphScript, ArcsInDegreesWithSignedSweep) {
  const Glyph g = parse_glyph_script(U'x', 8, "A4,7,3,160,-40 E4,5,3,5,90,450");
  ASSERT_EQ(g.elements.size(), 3u);  // the ellipse starts away from the arc's end: a move between
  const auto& a = std::get<CircularArc>(g.elements[0].geometry());
  expect_point(a.center, 4, 7);
  EXPECT_EQ(a.radius, 3);
  EXPECT_NEAR(a.start_angle, 160 * kPi / 180, 1e-15);
  EXPECT_NEAR(a.sweep, -200 * kPi / 180, 1e-15);  // clockwise
  EXPECT_FALSE(g.elements[1].laser());
  const auto& e = std::get<EllipticalArc>(g.elements[2].geometry());
  expect_point(e.center, 4, 5);
  EXPECT_EQ(e.rx, 3);
  EXPECT_EQ(e.ry, 5);
  EXPECT_EQ(e.rotation, 0);
  EXPECT_NEAR(e.sweep, 2 * kPi, 1e-15);
  expect_point(g.elements[2].start(), 4, 10);
}

TEST(GlyphScript, ArcStartingAtThePenContinuesTheStroke) {
  // The arc's computed start (4 + 3·cos(−90°), 0) differs from (4, 0) by ~1e-16: joined.
  const Glyph g = parse_glyph_script(U'b', 8, "M1,0 L4,0 E4,3.5,3,3.5,-90,90 L1,7");
  ASSERT_EQ(g.elements.size(), 3u);
  for (const Element& e : g.elements) EXPECT_TRUE(e.laser());
}

TEST(GlyphScript, LineEndingNearTheNextArcSnapsOntoItsStart) {
  const Glyph g = parse_glyph_script(U'&', 8, "M7.5,0 L2.044,6.244 A3.6,7.8,2.2,225,-45");
  ASSERT_EQ(g.elements.size(), 2u);
  EXPECT_LT((g.elements[0].end() - g.elements[1].start()).norm(), 1e-12);
  expect_point(g.elements[0].start(), 7.5, 0);
}

TEST(GlyphScript, CommandsRepeatOverFurtherGroups) {
  const Glyph g = parse_glyph_script(U'Z', 8, "M1,10 L7,10 1,0 7,0");
  ASSERT_EQ(g.elements.size(), 3u);
  expect_point(g.elements[2].end(), 7, 0);
}

TEST(GlyphScript, EmptyScriptIsABlankGlyph) {
  EXPECT_TRUE(parse_glyph_script(U' ', 5, "  ").elements.empty());
}

struct BadScript {
  const char* script;
  const char* token;    // must appear in the message
  const char* problem;  // must appear in the message
};
void PrintTo(const BadScript& b, std::ostream* os) { *os << '"' << b.script << '"'; }

class GlyphScriptErrors : public ::testing::TestWithParam<BadScript> {};

TEST_P(GlyphScriptErrors, NameTheGlyphAndTheToken) {
  const BadScript& bad = GetParam();
  try {
    parse_glyph_script(U'X', 8, bad.script);
    FAIL() << "accepted: " << bad.script;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_THAT(what, HasSubstr("'X' (U+0058)"));
    EXPECT_THAT(what, HasSubstr(std::string("'") + bad.token + "'"));
    EXPECT_THAT(what, HasSubstr(bad.problem));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, GlyphScriptErrors,
    ::testing::Values(BadScript{"M1,0 Q2,3", "Q", "unknown command"},
                      BadScript{"1,0 L2,3", "1,0", "before any command"},
                      BadScript{"L2,3", "2,3", "no pen position"},
                      BadScript{"M1,0 L3", "3", "takes 2 numbers, got 1"},
                      BadScript{"M1,0 L3,4,5", "3,4,5", "takes 2 numbers, got 3"},
                      BadScript{"M1,0 L3,#", "3,#", "bad number"},
                      BadScript{"M1,0 L3,", "3,", "bad number"},
                      BadScript{"M1,0 L3,,4", "3,,4", "bad number"},
                      BadScript{"M1,0 L1.2.3,4", "1.2.3,4", "bad number"},
                      BadScript{"E4,6,2.6,2000000000,20,270", "4,6,2.6,2000000000,20,270", "outside -1000000 to 1000000"},
                      BadScript{"M1,0 L", "L", "without coordinates"},
                      BadScript{"M L1,0", "M", "without coordinates"},
                      BadScript{"M1,0 L1,0", "1,0", "zero-length"},
                      BadScript{"M1,0 L2,0 M5,5", "M", "ends with a pen move"},
                      BadScript{"A0,0,-1,0,90", "0,0,-1,0,90", "radius must be positive"},
                      BadScript{"A0,0,1,30,30", "0,0,1,30,30", "sweep"},
                      BadScript{"E0,0,1,2,0,400", "0,0,1,2,0,400", "sweep"},
                      BadScript{"E0,0,0,2,0,90", "0,0,0,2,0,90", "radii must be positive"},
                      BadScript{"M5,5 A0,0,1,0,90", "0,0,1,0,90", "preceding M"},
                      // an arc ending 1.7e-6 short of the next arc: a tiny unmarked gap
                      BadScript{"A0,0,1,0,90 A0,0,1,90.0001,180", "0,0,1,90.0001,180",
                                "join exactly"}),
    [](const ::testing::TestParamInfo<BadScript>& info) { return "case" + std::to_string(info.index); });

TEST(GlyphScript, RejectsANonPositiveAdvance) {
  EXPECT_THROW(parse_glyph_script(U'X', 0, "M0,0 L1,1"), InputError);
}

}  // namespace
}  // namespace mark
