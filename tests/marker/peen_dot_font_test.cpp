// The built-in dot-matrix fonts: coverage, grid sizes, hand-counted glyphs, and refusals of
// malformed bitmaps and missing characters.
#include <gtest/gtest.h>

#include <string>

#include "fonts/error.hpp"
#include "marker/peen/dot_fonts.hpp"
#include "marker/peen/dot_stroke_font.hpp"

namespace mark {
namespace {

int count_dots(const DotFont& f, char32_t c) { return static_cast<int>(f.glyph(c).dots.size()); }

TEST(PeenDotFont, BuiltInFontsCoverSerialNumberCharacters) {
  for (std::string_view name : dot_font_names()) {
    const DotFont* f = find_dot_font(name);
    ASSERT_NE(f, nullptr) << name;
    std::u32string needed = U"0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ-.:/ ";
    if (name != "10x16") needed += U"#+?";
    for (char32_t c : needed) {
      const DotGlyph* g = f->find(c);
      ASSERT_NE(g, nullptr) << name << " lacks U+" << std::hex << static_cast<unsigned>(c);
      for (const DotCell& d : g->dots) {
        EXPECT_GE(d.col, 0);
        EXPECT_LT(d.col, f->columns());
        EXPECT_GE(d.row, 0);
        EXPECT_LT(d.row, f->rows());
      }
      if (c != U' ') {
        EXPECT_FALSE(g->dots.empty()) << name;
      }
    }
  }
  EXPECT_EQ(find_dot_font("6x9"), nullptr);
}

TEST(PeenDotFont, GridSizesAndHandCountedGlyphs) {
  EXPECT_EQ(dot_font_5x7().columns(), 5);
  EXPECT_EQ(dot_font_5x7().rows(), 7);
  EXPECT_EQ(dot_font_7x9().columns(), 7);
  EXPECT_EQ(dot_font_7x9().rows(), 9);
  EXPECT_EQ(dot_font_10x16().columns(), 10);
  EXPECT_EQ(dot_font_10x16().rows(), 16);
  // 5x7 "8": 3 + 2 + 2 + 3 + 2 + 2 + 3 dots; "1": 1 + 2 + 1·4 + 3; "-": 3; ".": 1.
  EXPECT_EQ(count_dots(dot_font_5x7(), U'8'), 17);
  EXPECT_EQ(count_dots(dot_font_5x7(), U'1'), 10);
  EXPECT_EQ(count_dots(dot_font_5x7(), U'-'), 3);
  EXPECT_EQ(count_dots(dot_font_5x7(), U'.'), 1);
  // 10x16 "8" (the patent's character), row by row: 6,2,2,2,2,2,2,6,2,2,2,2,2,2,2,6 = 44.
  EXPECT_EQ(count_dots(dot_font_10x16(), U'8'), 44);
  EXPECT_EQ(count_dots(dot_font_7x9(), U'H'), 2 * 9 + 5);
  // Cells read top-down, left to right: the first dot of 5x7 "1" is the top of its stem.
  EXPECT_EQ(dot_font_5x7().glyph(U'1').dots.front(), (DotCell{2, 0}));
}

TEST(PeenDotFont, MalformedBitmapsAndMissingGlyphsAreRefused) {
  DotFont f("test", 3, 2);
  f.add(U'A', {"#.#", ".#."});
  EXPECT_EQ(f.glyph(U'A').dots.size(), 3u);
  try {
    f.add(U'B', {"#.#"});
    FAIL() << "one row accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'B'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1 rows"), std::string::npos) << e.what();
  }
  EXPECT_THROW(f.add(U'C', {"#.#", ".#"}), InputError);
  try {
    f.add(U'D', {"#.#", ".x."});
    FAIL() << "'x' accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("row 1, column 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(f.glyph(U'Z'), MissingGlyphError);
  EXPECT_THROW(DotFont("flat", 5, 1), InputError);
}

TEST(PeenDotFont, AsStrokeFontPutsEveryDotOnItsPitchGrid) {
  const StrokeFont s = as_stroke_font(dot_font_5x7());
  EXPECT_DOUBLE_EQ(s.metrics().standard_height, 6.0);
  const Glyph& one = s.glyph(U'1');
  EXPECT_DOUBLE_EQ(one.advance, 6.0);
  ASSERT_EQ(one.elements.size(), 10u);
  // Top of the stem: column 2, row 0 → (2, 6) in pitches above the baseline; zero length, lit.
  EXPECT_EQ(one.elements[0].start(), Point(2, 6));
  EXPECT_EQ(one.elements[0].end(), Point(2, 6));
  EXPECT_TRUE(one.elements[0].laser());
  // Bottom bar on the baseline.
  EXPECT_DOUBLE_EQ(one.elements.back().start().y(), 0.0);
}

}  // namespace
}  // namespace mark
