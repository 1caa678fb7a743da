// Dot characters placed by the text layout: pitch from the height, advance of columns + 1, cells
// recovered through rotation, circles and mirroring; and "continuous" dots along stroke fonts.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/numbers.hpp"
#include "fonts/error.hpp"
#include "marker/peen/dot_fonts.hpp"
#include "marker/peen/dot_layout.hpp"

namespace mark {
namespace {

const Dot* find_dot(const DotText& t, std::size_t character, DotCell cell) {
  for (const Dot& d : t.dots)
    if (d.character == character && d.cell == cell) return &d;
  return nullptr;
}

void expect_frames_match_dots(const DotText& t) {
  ASSERT_EQ(t.cell_frames.size(), t.characters);
  for (const Dot& d : t.dots)
    EXPECT_LT((t.cell_position(d.character, d.cell) - d.pos_mm).norm(), 1e-9);
}

TEST(PeenDotLayout, LinearTextPitchAndAdvance) {
  LayoutOptions o;
  o.height_mm = 3.0;  // 5x7: 6 pitches → 0.5 mm pitch
  const DotText t = layout_dot_text("18", dot_font_5x7(), o);
  EXPECT_DOUBLE_EQ(t.pitch_mm, 0.5);
  EXPECT_EQ(t.characters, 2u);
  EXPECT_EQ(t.dots.size(), 10u + 17u);
  // "1": top of the stem at column 2, row 0 → (1.0, 3.0); bottom bar on the baseline.
  const Dot* top = find_dot(t, 0, {2, 0});
  ASSERT_NE(top, nullptr);
  EXPECT_NEAR(top->pos_mm.x(), 1.0, 1e-12);
  EXPECT_NEAR(top->pos_mm.y(), 3.0, 1e-12);
  // "8" starts one advance (6 pitches = 3 mm) later: its (1, 6) dot at (3.5, 0).
  const Dot* bottom = find_dot(t, 1, {1, 6});
  ASSERT_NE(bottom, nullptr);
  EXPECT_NEAR(bottom->pos_mm.x(), 3.5, 1e-12);
  EXPECT_NEAR(bottom->pos_mm.y(), 0.0, 1e-12);
  expect_frames_match_dots(t);
}

TEST(PeenDotLayout, SpacesCarryNoDotsButKeepTheAdvance) {
  LayoutOptions o;
  o.height_mm = 6.0;  // 1 mm pitch
  const DotText t = layout_dot_text("1 1", dot_font_5x7(), o);
  EXPECT_EQ(t.characters, 2u);
  const Dot* a = find_dot(t, 0, {2, 0});
  const Dot* b = find_dot(t, 1, {2, 0});
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(b->pos_mm.x() - a->pos_mm.x(), 12.0, 1e-12);  // two advances of 6 mm
}

TEST(PeenDotLayout, InclinedTextKeepsCellsAndRotatesDots) {
  LayoutOptions o;
  o.height_mm = 6.0;
  o.angle_deg = 30;
  const DotText t = layout_dot_text("L", dot_font_7x9(), o);  // 7x9: 8 pitches → 0.75 mm
  const Dot* corner = find_dot(t, 0, {6, 8});                 // right end of the foot
  ASSERT_NE(corner, nullptr);
  const double r = 6 * 0.75, a = 30 * kPi / 180;
  EXPECT_NEAR(corner->pos_mm.x(), r * std::cos(a), 1e-9);
  EXPECT_NEAR(corner->pos_mm.y(), r * std::sin(a), 1e-9);
  expect_frames_match_dots(t);
}

TEST(PeenDotLayout, CircularTextStandsOnTheCircle) {
  LayoutOptions o;
  o.height_mm = 3.0;
  o.circle = CircleFit{{0, 0}, 20, std::nullopt, false};
  const DotText t = layout_dot_text("HHHH", dot_font_5x7(), o);
  EXPECT_EQ(t.characters, 4u);
  // Each letter's baseline is the circle's tangent at the letter's centre (half the 3 mm advance
  // from its origin): a dot s mm along the baseline from there and h mm above it lies at
  // √((R + h)² + s²) from the centre.
  for (const Dot& d : t.dots) {
    const double s = d.cell.col * 0.5 - 1.5, h = (6 - d.cell.row) * 0.5;
    EXPECT_NEAR(d.pos_mm.norm(), std::hypot(20.0 + h, s), 1e-9);
  }
  expect_frames_match_dots(t);
}

TEST(PeenDotLayout, MirroredTextReadsCellsAsSeen) {
  LayoutOptions o;
  o.height_mm = 6.0;
  o.mirror = true;
  const DotText t = layout_dot_text("L", dot_font_5x7(), o);
  // Mirrored "L": the stem is on the right as seen, so the stem's cells are column 4.
  const Dot* stem_top = find_dot(t, 0, {4, 0});
  ASSERT_NE(stem_top, nullptr);
  EXPECT_EQ(find_dot(t, 0, {0, 0}), nullptr);
  // Seen columns increase to the right.
  const Dot* foot_left = find_dot(t, 0, {0, 6});
  ASSERT_NE(foot_left, nullptr);
  EXPECT_LT(foot_left->pos_mm.x(), stem_top->pos_mm.x());
  expect_frames_match_dots(t);
}

TEST(PeenDotLayout, MissingCharacterIsRefused) {
  EXPECT_THROW(layout_dot_text("a", dot_font_5x7(), LayoutOptions{}), MissingGlyphError);
}

// A stroke font with a line, a circle and a dot, standard height 10 units.
StrokeFont test_strokes() {
  FontMetrics m;
  m.cap_height = m.standard_height = 10;
  m.line_height = 14;
  m.word_spacing = 6;
  StrokeFont f("strokes", "test", m);
  Glyph i;
  i.code_point = U'I';
  i.elements = {Element::line({0, 0}, {0, 10}), Element::line({0, 10}, {3, 10}, false),
                Element::line({3, 10}, {3, 10})};
  i.advance = 6;
  f.add(i);
  Glyph o;
  o.code_point = U'O';
  o.elements = {Element::arc({5, 5}, 5, 0, 2 * kPi)};
  o.advance = 12;
  f.add(o);
  return f;
}

TEST(PeenStrokeDots, LinesGetEvenDotsNoFartherThanThePitch) {
  LayoutOptions o;
  o.height_mm = 10;  // 1 unit = 1 mm
  const Figure fig = layout_text("I", test_strokes(), o);
  const DotText t = dots_along_strokes(fig, 0.8);
  // 10 mm at ≤ 0.8 mm: 13 intervals → 14 dots, plus the lone dot; the pen move strikes nothing.
  ASSERT_EQ(t.dots.size(), 15u);
  for (int k = 0; k < 14; ++k) {
    EXPECT_NEAR(t.dots[k].pos_mm.x(), 0.0, 1e-12);
    EXPECT_NEAR(t.dots[k].pos_mm.y(), 10.0 * k / 13, 1e-12);
  }
  EXPECT_NEAR(t.dots[14].pos_mm.x(), 3.0, 1e-12);
  // Cells on the pitch grid, rows from the top.
  // The top dot is 12.5 pitches up, rounded away from zero to 13: the bottom is row 13.
  EXPECT_EQ(t.dots[13].cell.row, 0);
  EXPECT_EQ(t.dots[0].cell.row, 13);
  EXPECT_THROW(dots_along_strokes(fig, 0), InputError);
}

TEST(PeenStrokeDots, ClosedAndEllipticalArcsMergeTheirSeam) {
  LayoutOptions o;
  o.height_mm = 10;
  o.width_factor = 0.6;  // the circle becomes an exact ellipse 6 x 10 mm
  const Figure fig = layout_text("O", test_strokes(), o);
  ASSERT_EQ(fig.glyphs[0].elements[0].kind(), ElementKind::ellipse);
  const double pitch = 0.5;
  const DotText t = dots_along_strokes(fig, pitch);
  const double length = fig.glyphs[0].elements[0].length();
  // n = ceil(L / pitch) intervals give n + 1 dots; the last one lands on the first and is merged.
  EXPECT_EQ(t.dots.size(), static_cast<std::size_t>(std::ceil(length / pitch)));
  // Equal arc-length spacing: every neighbour gap ≤ pitch, and none closer than half a pitch.
  for (std::size_t i = 0; i < t.dots.size(); ++i) {
    const double gap = (t.dots[(i + 1) % t.dots.size()].pos_mm - t.dots[i].pos_mm).norm();
    EXPECT_LE(gap, pitch + 1e-9);
    EXPECT_GT(gap, pitch * 0.9);  // chords of ≈0.49 mm arcs
  }
  for (std::size_t i = 0; i < t.dots.size(); ++i)
    for (std::size_t j = i + 1; j < t.dots.size(); ++j)
      EXPECT_GE((t.dots[i].pos_mm - t.dots[j].pos_mm).norm(), pitch / 2);
}

}  // namespace
}  // namespace mark
