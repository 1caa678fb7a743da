// Hershey .jhf loader: Debian's roman simplex measured against the file, every Debian font, wrapped
// records, and every kind of malformed record with its line number.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fonts/loaders.hpp"
#include "loader_test_util.hpp"

namespace mark {
namespace {

using test::expect_font_error;
using test::expect_point;

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const StrokeFont& rowmans() {
  static const StrokeFont font = load_font_file(test::kHersheyDir + "/rowmans.jhf");
  return font;
}

TEST(LoaderJhf, RomanSimplexMetrics) {
  const StrokeFont& f = rowmans();
  EXPECT_EQ(f.name(), "rowmans");
  EXPECT_EQ(f.source(), test::kHersheyDir + "/rowmans.jhf");
  ASSERT_EQ(f.size(), 96u);  // U+0020 .. U+007F
  EXPECT_EQ(f.glyphs().begin()->first, U' ');
  EXPECT_EQ(f.glyphs().rbegin()->first, char32_t{0x7F});
  const FontMetrics& m = f.metrics();
  EXPECT_EQ(m.cap_height, 21);
  EXPECT_EQ(m.standard_height, 21);
  EXPECT_EQ(m.x_height, 14);   // 'x' top at file y = −5
  EXPECT_EQ(m.baseline, 9);    // file y of the baseline
  EXPECT_EQ(m.ascender, 25);   // brackets reach file y = −16
  EXPECT_EQ(m.descender, -7);  // descenders reach file y = +16
  EXPECT_EQ(m.line_height, 32);
  EXPECT_EQ(m.word_spacing, 16);  // the space's bearings −8 .. +8
  EXPECT_EQ(m.letter_spacing, 0);
}

TEST(LoaderJhf, CapitalHSpansBaselineToCapHeight) {
  // "  508  9G]KFK[ RYFY[ RKPYP": bearings −11/+11; stems at x −7, +7; crossbar at file y −2.
  const Glyph& h = rowmans().glyph(U'H');
  EXPECT_EQ(h.advance, 22);
  const Box b = h.bounds();
  expect_point(b.min, 4, 0);
  expect_point(b.max, 18, 21);
  ASSERT_EQ(h.elements.size(), 5u);
  const bool laser[] = {true, false, true, false, true};
  const double pts[5][4] = {
      {4, 21, 4, 0}, {4, 0, 18, 21}, {18, 21, 18, 0}, {18, 0, 4, 11}, {4, 11, 18, 11}};
  for (int i = 0; i < 5; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(h.elements[i].laser(), laser[i]);
    expect_point(h.elements[i].start(), pts[i][0], pts[i][1]);
    expect_point(h.elements[i].end(), pts[i][2], pts[i][3]);
  }
}

TEST(LoaderJhf, CapitalAJoinsItsLegsAtTheApex) {
  // "  501  9I[RFJ[ RRFZ[ RMTWT": both legs start at the apex (0, −12); the first is reversed so
  // the pen draws them as one stroke, then moves to the crossbar.
  const Glyph& a = rowmans().glyph(U'A');
  EXPECT_EQ(a.advance, 18);
  ASSERT_EQ(a.elements.size(), 4u);
  EXPECT_TRUE(a.elements[0].laser());
  expect_point(a.elements[0].start(), 1, 0);
  expect_point(a.elements[0].end(), 9, 21);
  EXPECT_TRUE(a.elements[1].laser());
  expect_point(a.elements[1].end(), 17, 0);
  EXPECT_FALSE(a.elements[2].laser());
  expect_point(a.elements[2].end(), 4, 7);
  EXPECT_TRUE(a.elements[3].laser());
  expect_point(a.elements[3].end(), 14, 7);
}

TEST(LoaderJhf, SpaceHasAdvanceAndNoElements) {
  const Glyph& space = rowmans().glyph(U' ');
  EXPECT_EQ(space.advance, 16);
  EXPECT_TRUE(space.elements.empty());
}

TEST(LoaderJhf, DigitZeroIsOneClosedStroke) {
  // "  700 18H\QFNGLJKOKRLWNZQ[S[VZXWYRYOXJVGSFQF": 17 points, pen never lifted.
  const Glyph& zero = rowmans().glyph(U'0');
  EXPECT_EQ(zero.advance, 20);
  ASSERT_EQ(zero.elements.size(), 16u);
  EXPECT_EQ(test::count_travel(zero), 0u);
  expect_point(zero.elements.front().start(), 9, 21);  // Q F
  expect_point(zero.elements[1].end(), 4, 17);         // L J
  expect_point(zero.elements.back().end(), 9, 21);
}

TEST(LoaderJhf, AllDebianFontsLoad) {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::kHersheyDir)) {
    if (entry.path().extension() != ".jhf") continue;
    ++files;
    SCOPED_TRACE(entry.path().string());
    Warnings warnings;
    const StrokeFont f = load_font_file(entry.path().string(), &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_GE(f.size(), 96u);
    EXPECT_GT(f.metrics().cap_height, 0);
    EXPECT_EQ(f.metrics().baseline, 9);
    for (const auto& [cp, g] : f.glyphs()) {
      test::expect_continuous(g, 0);
      if (!g.elements.empty()) {
        EXPECT_TRUE(g.elements.front().laser());
        EXPECT_TRUE(g.elements.back().laser());
      }
    }
  }
  EXPECT_EQ(files, 32u);
  EXPECT_EQ(load_font_file(test::kHersheyDir + "/japanese.jhf").size(), 193u);
}

// Re-wraps every record of `text` after `width` characters, as the USENET distribution did.
std::string wrap_records(std::string_view text, std::size_t width) {
  std::string out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    while (line.size() > width) {
      out.append(line.substr(0, width)).push_back('\n');
      line.remove_prefix(width);
    }
    out.append(line).push_back('\n');
    pos = end + 1;
  }
  return out;
}

void expect_same_font(const StrokeFont& a, const StrokeFont& b) {
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [cp, ga] : a.glyphs()) {
    const Glyph& gb = b.glyph(cp);
    EXPECT_EQ(ga.advance, gb.advance);
    ASSERT_EQ(ga.elements.size(), gb.elements.size()) << static_cast<unsigned>(cp);
    for (std::size_t i = 0; i < ga.elements.size(); ++i) {
      EXPECT_EQ(ga.elements[i].laser(), gb.elements[i].laser());
      EXPECT_EQ(ga.elements[i].start(), gb.elements[i].start());
      EXPECT_EQ(ga.elements[i].end(), gb.elements[i].end());
    }
  }
}

TEST(LoaderJhf, WrappedRecordsParseLikeUnwrappedOnes) {
  const std::string text = read_text(test::kHersheyDir + "/gothicger.jhf");  // up to 143 pairs
  const StrokeFont plain = parse_jhf(text, "gothicger.jhf");
  // 72 is the USENET width; 13 and 9 split pen-up pairs " R" across lines.
  for (std::size_t width : {72u, 13u, 9u}) {
    SCOPED_TRACE(width);
    const std::string wrapped = wrap_records(text, width);
    ASSERT_NE(wrapped, text);
    expect_same_font(plain, parse_jhf(wrapped, "gothicger.jhf"));
  }
}

TEST(LoaderJhf, WrappedFixtureMatchesDebianFile) {
  // tests/fonts/data/rowmans_wrapped.jhf: rowmans' first 40 records wrapped at 50 columns.
  const StrokeFont wrapped = load_font_file(test::kDataDir + "/rowmans_wrapped.jhf");
  const StrokeFont full = rowmans();
  ASSERT_EQ(wrapped.size(), 40u);
  for (const auto& [cp, g] : wrapped.glyphs()) {
    const Glyph& d = full.glyph(cp);
    ASSERT_EQ(g.elements.size(), d.elements.size());
    for (std::size_t i = 0; i < g.elements.size(); ++i)
      EXPECT_EQ(g.elements[i].end(), d.elements[i].end());
  }
}

// A record for a test: glyph number 1, count and body as given.
std::string record(int pairs, std::string_view body) {
  char head[16];
  std::snprintf(head, sizeof head, "%5d%3d", 1, pairs);
  return std::string(head) + std::string(body) + "\n";
}

const std::string kGood = record(3, "MWRFRT");  // bearings −5/+5, one vertical line

TEST(LoaderJhf, RecordHelperMakesAValidFont) {
  const StrokeFont f = parse_jhf(kGood + kGood, "t.jhf");
  EXPECT_EQ(f.size(), 2u);
  const Glyph& g = f.glyph(U'!');
  EXPECT_EQ(g.advance, 10);
  ASSERT_EQ(g.elements.size(), 1u);
  expect_point(g.elements[0].start(), 5, 21);
  expect_point(g.elements[0].end(), 5, 7);
}

TEST(LoaderJhf, CrLfLineEndsAndTrailingBlankLinesAreAccepted) {
  const StrokeFont f = parse_jhf("    1  3MWRFRT\r\n    2  2MWRF\r\n\r\n  \n", "t.jhf");
  EXPECT_EQ(f.size(), 2u);
  EXPECT_TRUE(f.glyph(U'!').elements.empty());  // a single point draws nothing
}

TEST(LoaderJhf, MalformedRecordsNameTheirLine) {
  const std::string s = "bad.jhf";
  const auto fails = [&](const std::string& text, std::size_t line, std::string_view what) {
    SCOPED_TRACE(text);
    expect_font_error([&] { parse_jhf(text, s); }, s, line, what);
  };
  fails(kGood + "  5x1  3MWRFRT\n", 2, "bad glyph number");
  fails(kGood + "       3MWRFRT\n", 2, "bad glyph number");
  fails(kGood + "    1 x3MWRFRT\n", 2, "bad pair count");
  fails(kGood + "    1  -MWRFRT\n", 2, "bad pair count");
  fails(kGood + "    1  0MW\n", 2, "pair count 0");
  fails(kGood + "  501\n", 2, "shorter than its 8 columns");
  fails(kGood + record(4, "MWRFRT"), 2,
        "truncated record: pair count 4 needs 8 coordinate characters, found 6");
  fails(record(4, "MWRFRT") + kGood, 1,
        "truncated record");  // next line is a record, not a continuation
  fails(kGood + record(4, "MWRF") + "\n" + kGood, 2,
        "truncated record");  // a blank line never continues
  fails(kGood + kGood + record(2, "MWRFRT"), 3, "longer than its pair count 2");
  fails(record(3, "MWRFRT RQ"), 1, "longer than its pair count");
  fails(kGood + record(3, "MWRF") + "RTQQ\n", 3,
        "longer than its pair count");  // wrapped, too long
  fails(kGood + record(3, "MWRF Q"), 2, "pair 3 ' Q' is neither a point nor the pen-up");
  fails(kGood + record(3, "MWRF\tT"), 2, "pair 3");
  fails(kGood + record(3, "MWRF\xc3\xa9"), 2, "pair 3");
  fails(kGood + record(3, " WRFRT"), 2, "bad bearing pair");
  fails(kGood + record(3, "WMRFRT"), 2, "right bearing -5 lies left of left bearing 5");
  fails(kGood + "\n" + kGood, 2, "blank line between glyph records");
  fails("", 1, "no glyphs");
  fails("\n\n", 2, "no glyphs");
  fails(std::string("\x7f"
                    "ELF\x02\x01\x01\0\0\0",
                    10) +
            "\n",
        1, "bad glyph number '\\x7FELF\\x02' in columns 1-5");  // binary bytes escaped
  fails(std::string("    1  3MW\0FRT\n", 15), 1, "pair 2 '\\x00F'");
  fails("    1  3MWRF\xc3T\n", 1, "pair 3 '\\xC3T'");
}

TEST(LoaderJhf, TooManyRecordsIsAnError) {
  std::string text;
  const std::string one = record(1, "RR");
  for (int i = 0; i < 0xD7FF - 0x20 + 2; ++i) text += one;
  expect_font_error([&] { parse_jhf(text, "many.jhf"); }, "many.jhf", 0xD7FF - 0x20 + 2,
                    "too many glyph records");
}

}  // namespace
}  // namespace mark
