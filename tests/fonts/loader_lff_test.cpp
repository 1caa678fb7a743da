// LibreCAD .lff loader: bulge arcs computed by hand from standard.lff, glyph references, all of
// Debian's 46 files with their known defects, and malformed input with line numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>

#include "base/numbers.hpp"
#include "fonts/loaders.hpp"
#include "fonts/stroke_join.hpp"
#include "loader_test_util.hpp"

namespace mark {
namespace {

using test::expect_font_error;
using test::expect_point;

const StrokeFont& standard() {
  static const StrokeFont font = load_font_file(test::kLibreCadDir + "/standard.lff");
  return font;
}

const CircularArc& lff_arc_of(const Element& e) {
  EXPECT_EQ(e.kind(), ElementKind::arc);
  return std::get<CircularArc>(e.geometry());
}

TEST(LoaderLff, StandardMetrics) {
  Warnings warnings;
  const StrokeFont f = load_font_file(test::kLibreCadDir + "/standard.lff", &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(f.name(), "standard");
  EXPECT_EQ(f.size(), 220u);
  const FontMetrics& m = f.metrics();
  EXPECT_EQ(m.cap_height, 9);
  EXPECT_EQ(m.standard_height, 9);
  EXPECT_EQ(m.x_height, 6);
  EXPECT_EQ(m.baseline, 0);
  EXPECT_DOUBLE_EQ(m.line_height, 9 * 1.6);  // LibreCAD: 9 × 1.6 × LineSpacingFactor 1
  EXPECT_EQ(m.word_spacing, 6.75);
  EXPECT_EQ(m.letter_spacing, 0);    // already in every advance
  EXPECT_EQ(f.find(U' '), nullptr);  // the layout uses word_spacing
}

TEST(LoaderLff, CapitalH) {
  // [0048] H: 0,0;0,9 / 5,0;5,9 / 0,5;5,5 — advance = rightmost x 5 + LetterSpacing 3.
  const Glyph& h = standard().glyph(U'H');
  EXPECT_EQ(h.advance, 8);
  ASSERT_EQ(h.elements.size(), 5u);
  EXPECT_EQ(test::count_travel(h), 2u);
  expect_point(h.elements[0].start(), 0, 0);
  expect_point(h.elements[0].end(), 0, 9);
  EXPECT_FALSE(h.elements[1].laser());
  expect_point(h.elements[2].start(), 5, 0);
  expect_point(h.elements[4].end(), 5, 5);
}

TEST(LoaderLff, PercentRingIsTwoSemicircles) {
  // [0025] %: "3,7.5;0,7.5,A1;3,7.5,A1". The bulge on a vertex belongs to the segment ending there:
  // (3,7.5)→(0,7.5) with bulge 1 (sweep 4·atan 1 = π, counter-clockwise) is the upper half of the
  // circle about (1.5, 7.5) with radius 1.5, and (0,7.5)→(3,7.5) the lower half.
  const Glyph& pct = standard().glyph(U'%');
  EXPECT_EQ(pct.advance, 11);  // rightmost x 8 + 3
  std::vector<const Element*> arcs;
  for (const Element& e : pct.elements)
    if (e.kind() == ElementKind::arc) arcs.push_back(&e);
  ASSERT_EQ(arcs.size(), 4u);
  const CircularArc& upper = lff_arc_of(*arcs[0]);
  expect_point(upper.center, 1.5, 7.5);
  EXPECT_NEAR(upper.radius, 1.5, 1e-12);
  EXPECT_NEAR(upper.sweep, kPi, 1e-12);
  expect_point(arcs[0]->start(), 3, 7.5);
  expect_point(arcs[0]->point_at(0.5), 1.5, 9);
  expect_point(arcs[0]->end(), 0, 7.5);
  expect_point(arcs[1]->point_at(0.5), 1.5, 6);
  expect_point(arcs[1]->end(), 3, 7.5);
  // The lower ring "8,1.5;5,1.5,A1;8,1.5,A1" about (6.5, 1.5).
  expect_point(lff_arc_of(*arcs[2]).center, 6.5, 1.5);
  expect_point(arcs[2]->point_at(0.5), 6.5, 3);
  expect_point(arcs[3]->point_at(0.5), 6.5, 0);
  // The ring is closed and drawn without lifting the laser; two moves join the three strokes.
  EXPECT_EQ(test::count_travel(pct), 2u);
  test::expect_continuous(pct);
}

TEST(LoaderLff, CapitalCCornersAreClockwiseQuarterArcs) {
  // [0043] C: "4,0;2,0;0,2,A-0.414214;0,7;2,9,A-0.414214;4,9". Bulge −0.414214 ≈ −tan 22.5°:
  // a clockwise quarter circle; from (2,0) to (0,2) its centre is (2,2), radius 2, and its middle
  // (2 − √2, 2 − √2).
  const Glyph& c = standard().glyph(U'C');
  ASSERT_EQ(c.elements.size(), 5u);
  EXPECT_EQ(test::count_travel(c), 0u);
  const CircularArc& lower = lff_arc_of(c.elements[1]);
  const double sweep = 4 * std::atan(-0.414214);
  EXPECT_NEAR(lower.sweep, sweep, 1e-12);
  EXPECT_NEAR(lower.sweep, -kPi / 2, 1e-5);
  expect_point(lower.center, 2, 2, 1e-5);
  EXPECT_NEAR(lower.radius, std::sqrt(8.0) / (2 * std::sin(std::abs(sweep) / 2)), 1e-12);
  expect_point(c.elements[1].point_at(0.5), 2 - std::sqrt(2.0), 2 - std::sqrt(2.0), 1e-5);
  const CircularArc& upper = lff_arc_of(c.elements[3]);
  expect_point(upper.center, 2, 7, 1e-5);
  expect_point(c.elements[3].end(), 2, 9);
  EXPECT_EQ(c.advance, 7);
}

TEST(LoaderLff, ReferenceCopiesTheReferencedGlyph) {
  // [0051] Q: "C004f" then "6,0;4,2": the whole O plus the tail.
  const Glyph& o = standard().glyph(U'O');
  const Glyph& q = standard().glyph(U'Q');
  ASSERT_EQ(q.elements.size(), o.elements.size() + 2);  // a move and the tail
  for (std::size_t i = 0; i < o.elements.size(); ++i) {
    EXPECT_EQ(q.elements[i].kind(), o.elements[i].kind());
    EXPECT_EQ(q.elements[i].start(), o.elements[i].start());
  }
  EXPECT_FALSE(q.elements[o.elements.size()].laser());
  expect_point(q.elements.back().start(), 6, 0);
  expect_point(q.elements.back().end(), 4, 2);
}

TEST(LoaderLff, AllDebianFontsLoadWithTheirKnownDefects) {
  const std::map<std::string, std::size_t> expected_warnings = {
      {"unicode", 2},   // two malformed vertices
      {"kst32b", 5},    // duplicate glyphs (first kept, as in LibreCAD)
      {"cursive", 1},   // duplicate U+2205
      {"greek_ol", 1},  // "[[038c]"
      {"syastro", 1},  {"symap", 1}, {"symath", 1}, {"symeteo", 1}, {"symusic", 1},  // stray block
  };
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::kLibreCadDir)) {
    if (entry.path().extension() != ".lff") continue;
    ++files;
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE(name);
    Warnings warnings;
    const StrokeFont f = load_font_file(entry.path().string(), &warnings);
    const auto it = expected_warnings.find(name);
    EXPECT_EQ(warnings.size(), it == expected_warnings.end() ? 0u : it->second);
    EXPECT_GT(f.size(), 40u);
    EXPECT_GT(f.metrics().cap_height, 0);
    for (const auto& [cp, g] : f.glyphs()) {
      ASSERT_FALSE(g.elements.empty());
      EXPECT_TRUE(g.elements.front().laser());
      EXPECT_TRUE(g.elements.back().laser());
      for (std::size_t i = 1; i < g.elements.size(); ++i)
        EXPECT_FALSE(!g.elements[i].laser() && !g.elements[i - 1].laser()) << "two moves in a row";
      // Pieces whose ends meet within the shared join tolerance are one stroke, with no pen move
      // between them (amiri-regular's arcs miss their neighbours by 6e-4 of its 9 units).
      test::expect_continuous(g, join_tolerance(f.metrics().cap_height));
    }
  }
  EXPECT_EQ(files, 46u);
}

TEST(LoaderLff, UnicodeSkipsItsTwoMalformedVertices) {
  Warnings warnings;
  const std::string path = test::kLibreCadDir + "/unicode.lff";
  const StrokeFont f = load_font_file(path, &warnings);
  EXPECT_EQ(f.size(), 2622u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], path + ":352: skipped malformed vertex '6.,1.5A.41'");
  EXPECT_EQ(warnings[1], path + ":85349: skipped malformed vertex '8.'");
  // [ff0c] "8.,1.41;8.;7.19,-1.41": the polyline goes on from the last good vertex.
  const Glyph& comma = f.glyph(U'\uFF0C');
  ASSERT_EQ(comma.elements.size(), 1u);
  expect_point(comma.elements[0].start(), 8, 1.41);
  expect_point(comma.elements[0].end(), 7.19, -1.41);
}

// --- synthetic files -----------------------------------------------------------------------

const std::string kHeader = "# Format: LibreCAD Font 1\n# LetterSpacing: 2\n# WordSpacing: 5\n";

TEST(LoaderLff, BulgeOnTheFirstVertexIsIgnoredAndArcsEndWhereTheyShould) {
  const StrokeFont f = parse_lff(kHeader + "\n[0041] A\n0,0,A5;2,0,A1\n", "t.lff");
  const Glyph& a = f.glyph(U'A');
  ASSERT_EQ(a.elements.size(), 1u);
  const CircularArc& arc = lff_arc_of(a.elements[0]);
  expect_point(arc.center, 1, 0);
  EXPECT_NEAR(arc.radius, 1, 1e-12);
  expect_point(a.elements[0].point_at(0.5), 1, -1);  // counter-clockwise from (0,0): below
  EXPECT_EQ(a.advance, 2 + 2);
}

TEST(LoaderLff, HeaderValuesAndSpacing) {
  const StrokeFont f = parse_lff(
      "# letterspacing: +1.5\n#WordSpacing:4\n# LineSpacingFactor: 2\n# Name: x: y\n# just a note\n"
      " # Author: leading space\n\n[41] A\n0,0;1,9\n\n[0020] space\n\n",
      "t.lff");
  EXPECT_EQ(f.glyph(U'A').advance, 2.5);
  EXPECT_EQ(f.metrics().word_spacing, 4);
  EXPECT_DOUBLE_EQ(f.metrics().line_height, 2 * 9 * 1.6);
  EXPECT_EQ(f.find(U' '), nullptr);      // empty glyphs are dropped, as LibreCAD does
  EXPECT_EQ(f.metrics().cap_height, 9);  // no H or I: the ascender
}

TEST(LoaderLff, ByteOrderMarkIsSkipped) {
  Warnings w;
  const StrokeFont f =
      parse_lff("\xEF\xBB\xBF# LetterSpacing: 1\n\n[0041] A\n0,0;1,1\n", "bom.lff", &w);
  EXPECT_TRUE(w.empty());
  EXPECT_EQ(f.glyph(U'A').advance, 2);
}

TEST(LoaderLff, ReferencesResolveForwardAndNested) {
  const StrokeFont f = parse_lff(kHeader +
                                     "[0043] C\nC0042\n2,0;2,1\n\n"
                                     "[0042] B\nC41\n1,0;1,1\n\n"
                                     "[0041] A\n0,0;0,1\n",
                                 "t.lff");
  const Glyph& c = f.glyph(U'C');
  EXPECT_EQ(test::count_lit(c), 3u);
  EXPECT_EQ(test::count_travel(c), 2u);
  expect_point(c.elements.front().start(), 0, 0);
  expect_point(c.elements.back().end(), 2, 1);
  EXPECT_EQ(c.advance, 4);
}

TEST(LoaderLff, LongReferenceChainsDoNotRecurse) {
  std::string text = kHeader + "[1] x\n0,0;1,1\n\n";
  for (int cp = 2; cp <= 20000; ++cp) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "[%x] x\nC%x\n\n", cp, cp - 1);
    text += buf;
  }
  const StrokeFont f = parse_lff(text, "chain.lff");
  EXPECT_EQ(f.glyph(20000).elements.size(), 1u);
}

TEST(LoaderLff, ReferenceExpansionIsBounded) {
  // Each glyph draws the previous one twice: 2^30 elements if nobody stopped it.
  std::string text = kHeader + "[100] x\n0,0;1,1\n\n";
  for (int cp = 0x101; cp <= 0x100 + 30; ++cp) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "[%x] x\nC%x\nC%x\n\n", cp, cp - 1, cp - 1);
    text += buf;
  }
  try {
    parse_lff(text, "bomb.lff");
    ADD_FAILURE() << "no error";
  } catch (const FontFileError& e) {
    EXPECT_NE(std::string(e.what()).find("expand to more than 2000000 elements"),
              std::string::npos);
  }
}

TEST(LoaderLff, SkippedDefectsAreWarnings) {
  Warnings w;
  const StrokeFont f = parse_lff(kHeader +
                                     "\n[0041] A\n0,0;1;x,2;3,4,B1;1,1,A;2,2,3,4;5,5\n\n"
                                     "[0041] again\n9,9;8,8\n\n"
                                     "1,1;2,2\n3,3;4,4\n",
                                 "w.lff", &w);
  ASSERT_EQ(w.size(), 7u);
  EXPECT_EQ(w[0], "w.lff:6: skipped malformed vertex '1'");
  EXPECT_EQ(w[1], "w.lff:6: skipped malformed vertex 'x,2'");
  EXPECT_EQ(w[2], "w.lff:6: skipped malformed vertex '3,4,B1'");
  EXPECT_EQ(w[3], "w.lff:6: skipped malformed vertex '1,1,A'");
  EXPECT_EQ(w[4], "w.lff:6: skipped malformed vertex '2,2,3,4'");
  EXPECT_EQ(w[5], "w.lff:8: duplicate glyph 'A' (U+0041) ignored (first defined at line 5)");
  EXPECT_EQ(w[6],
            "w.lff:11: ignored 2 lines outside any glyph (no '[XXXX]' header above since the last "
            "blank line)");
  const Glyph& a = f.glyph(U'A');
  ASSERT_EQ(a.elements.size(), 1u);  // (0,0)→(5,5), the first definition
  expect_point(a.elements[0].end(), 5, 5);
}

TEST(LoaderLff, MalformedFilesNameTheLine) {
  const std::string s = "bad.lff";
  const auto fails = [&](const std::string& text, std::size_t line, std::string_view what) {
    SCOPED_TRACE(text);
    expect_font_error([&] { parse_lff(text, s); }, s, line, what);
  };
  const std::string ok = "[0041] A\n0,0;1,1\n\n";
  fails("# LetterSpacing: abc\n" + ok, 1, "LetterSpacing 'abc' is not a number");
  fails("# LetterSpacing: 3 units\n" + ok, 1, "LetterSpacing '3 units' is not a number");
  fails("# WordSpacing: -1\n" + ok, 1, "WordSpacing '-1' is negative");
  fails("# LineSpacingFactor: 0\n" + ok, 1, "LineSpacingFactor '0' is not positive");
  fails("# LineSpacingFactor: nan\n" + ok, 1, "is not finite");
  fails("# WordSpacing: 1e400\n" + ok, 1, "is out of range");
  fails("# Encoding: EBCDIC\n" + ok, 1, "unsupported Encoding 'EBCDIC'");
  fails(ok + "[00G1] x\n0,0;1,1\n", 4, "bad glyph header '[00G1] x'");
  fails(ok + "[] x\n", 4, "no closing ']'");
  fails(ok + "[0041 x\n", 4, "no closing ']'");
  fails(ok + "[110000] x\n", 4, "bad glyph header");
  fails(ok + "[D800] x\n", 4, "bad glyph header");
  fails(ok + "[1234567] x\n", 4, "bad glyph header");
  fails(ok + "[#] x\n", 4, "bad glyph header");
  fails(ok + "[0042] B\nCxyz\n", 5, "bad glyph reference 'Cxyz'");
  fails(ok + "[0042] B\nC\n", 5, "bad glyph reference");
  fails(ok + "[0042] B\nC0099\n", 5,
        "glyph reference C0099 in 'B' (U+0042): the font has no glyph");
  fails(ok + "[0042] B\n0,0;1,1\nC0043\n\n[0043] C\nC0042\n", 9, "glyph reference cycle");
  fails(ok + "[0042] B\nC0042\n", 5,
        "glyph reference cycle: C0042 in 'B' (U+0042) leads back to 'B' (U+0042)");
  fails(ok + "[0042] B\nnan,0;1,1\n", 5, "number 'nan' in vertex 'nan,0' is not finite");
  fails(ok + "[0042] B\n0,inf;1,1\n", 5, "is not finite");
  fails(ok + "[0042] B\n0,0;1,1,A-inf\n", 5, "is not finite");
  fails(ok + "[0042] B\n1e7,0;1,1\n", 5, "is out of range");
  fails(ok + "[0042] B\n0,0;1,1\n0,0;\x01\n", 6, "control byte 0x01 at column 5");
  fails(ok + std::string("[0042] B\n0,0;1,1\0\n", 17), 5, "control byte 0x00");
  fails(ok + "[0042] \xff\n", 4, "invalid UTF-8");
  fails("# Format: LibreCAD Font 1\n# Name: empty\n", 2, "no glyphs");
  fails("", 1, "no glyphs");
  fails("[0020] space\n\n", 2, "no glyphs");
}

}  // namespace
}  // namespace mark
