// Filling laid-out text: every glyph keeps its place and order, hatch lines are lit elements
// with laser-off moves between them; serpentine blocks jump far less than a raster hatch; a
// single-line font is refused with the glyph named; parameters outside their ranges are refused.
#include <gtest/gtest.h>

#include <cmath>

#include "base/error.hpp"
#include "fonts/catalog.hpp"
#include "marker/fill/fill.hpp"
#include "marker/fill/fill_region.hpp"
#include "marker/fill/hatch_order.hpp"
#include "marker/plan/stroke.hpp"
#include "tests/marker/fill/fill_test_support.hpp"

namespace mark {
namespace {

Figure dejavu_text(const std::string& text, double height) {
  LayoutOptions o;
  o.height_mm = height;
  return layout_text(text, test::outline_font(test::kDejaVuSans), o);
}

TEST(FillFigure, GlyphsKeepTheirOrderAndHatchLinesAreLitStrokes) {
  const Figure text = dejavu_text("H8", 5);
  FillOptions o;
  o.sets = {{0, 0.05}};
  FillStats stats;
  const Figure filled = fill_figure(text, o, &stats);
  ASSERT_EQ(filled.glyphs.size(), 2u);
  EXPECT_EQ(filled.glyphs[0].code_point, U'H');
  EXPECT_EQ(filled.glyphs[1].code_point, U'8');
  std::size_t lit = 0;
  for (const PlacedGlyph& g : filled.glyphs)
    for (std::size_t k = 0; k < g.elements.size(); ++k) {
      lit += g.elements[k].laser();
      // Lit and unlit alternate: every hatch line is its own stroke.
      if (k > 0) {
        EXPECT_NE(g.elements[k].laser(), g.elements[k - 1].laser());
      }
    }
  EXPECT_EQ(lit, stats.hatch_lines);
  EXPECT_EQ(strokes_of(filled).size(), stats.hatch_lines);
  // Lines of both glyphs at the same heights: the scanlines are fixed in the field frame.
  EXPECT_NEAR(std::fmod(filled.glyphs[0].elements[0].start().y() / 0.05 + 1000, 1.0), 0.5, 1e-6);
  EXPECT_NEAR(std::fmod(filled.glyphs[1].elements[0].start().y() / 0.05 + 1000, 1.0), 0.5, 1e-6);
  // The hatched area covers the letters (inset 20 µm: a band of perimeter × 0.02 is left out).
  EXPECT_NEAR(stats.hatch_length_mm * 0.05 / stats.area_mm2, 0.9, 0.08);
}

TEST(FillFigure, SerpentineBlocksJumpFarLessThanARasterHatch) {
  const Figure text = dejavu_text("SN 2026-0042 W", 3);
  FillOptions o;
  FillStats ordered, raster;
  fill_figure(text, o, &ordered);
  o.order = HatchOrder::raster;
  o.direction = HatchDirection::unidirectional;
  fill_figure(text, o, &raster);
  EXPECT_EQ(ordered.hatch_lines, raster.hatch_lines);
  EXPECT_NEAR(ordered.hatch_length_mm, raster.hatch_length_mm, 1e-9);
  EXPECT_LT(ordered.jump_length_mm, 0.25 * raster.jump_length_mm);
  std::printf("jumps: %.0f mm ordered, %.0f mm raster (%zu lines)\n", ordered.jump_length_mm,
              raster.jump_length_mm, ordered.hatch_lines);
}

TEST(FillFigure, SerpentineAlternatesAndUnidirectionalDoesNot) {
  const std::vector<Contour> square = {rectangle_contour(test::box(0, 0, 2, 1))};
  FillOptions o;
  o.sets = {{0, 0.1}};
  o.inset_mm = 0;
  Point at(-1, -1);
  const Filled bi = fill_contours(square, o, at);
  ASSERT_EQ(bi.stats.hatch_lines, 10u);
  std::vector<double> dx;
  for (const Element& e : bi.elements)
    if (e.laser()) dx.push_back(e.end().x() - e.start().x());
  for (std::size_t k = 1; k < dx.size(); ++k) EXPECT_LT(dx[k] * dx[k - 1], 0) << k;
  // Serpentine: each jump is one spacing.
  EXPECT_NEAR(bi.stats.jump_length_mm, std::hypot(1.0, 1.05) + 9 * 0.1, 1e-9);
  o.direction = HatchDirection::unidirectional;
  at = Point(-1, -1);
  const Filled uni = fill_contours(square, o, at);
  for (const Element& e : uni.elements)
    if (e.laser()) {
      EXPECT_GT(e.end().x(), e.start().x());
    }
}

TEST(FillFigure, CrossHatchDrawsEachSetAtItsAngle) {
  const std::vector<Contour> square = {rectangle_contour(test::box(0, 0, 1, 1))};
  FillOptions o;
  o.sets = {{0, 0.1}, {90, 0.1}};
  o.inset_mm = 0;
  Point at(0, 0);
  const Filled f = fill_contours(square, o, at);
  ASSERT_EQ(f.stats.hatch_lines, 20u);
  std::size_t horizontal = 0, vertical = 0;
  for (const Element& e : f.elements) {
    if (!e.laser()) continue;
    const Point d = e.end() - e.start();
    horizontal += std::abs(d.y()) < 1e-12;
    vertical += std::abs(d.x()) < 1e-12;
  }
  EXPECT_EQ(horizontal, 10u);
  EXPECT_EQ(vertical, 10u);
}

TEST(FillFigure, SingleLineFontIsRefusedNamingTheGlyph) {
  LayoutOptions lo;
  const Figure f = layout_text("A", builtin_font(), lo);
  try {
    fill_figure(f, FillOptions{});
    FAIL() << "a single-line glyph was filled";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'A' (U+0041)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("closed"), std::string::npos) << e.what();
  }
}

TEST(FillFigure, ParametersOutsideTheirRangesAreRefused) {
  const auto message = [](FillOptions o) {
    try {
      check_fill_options(o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  FillOptions o;
  o.sets = {{0, 0}};
  EXPECT_EQ(message(o), "hatch spacing: 0 is outside the range 0.001 to 10 mm");
  o.sets = {{NAN, 0.05}};
  EXPECT_EQ(message(o), "hatch angle: nan is outside the range -360 to 360 degrees");
  o = FillOptions{};
  o.inset_mm = -1;
  EXPECT_EQ(message(o), "hatch inset: -1 is outside the range 0 to 5 mm");
  o = FillOptions{};
  o.contour_passes = 1000;
  EXPECT_EQ(message(o), "contour passes: 1000 is outside the range 0 to 100");
  o = FillOptions{};
  o.sets.clear();
  EXPECT_NE(message(o).find("nothing would be marked"), std::string::npos);
}

TEST(FillFigure, AbsurdSpacingForTheSizeIsRefusedNotAttempted) {
  const std::vector<Contour> big = {rectangle_contour(test::box(-50, -50, 50, 50))};
  FillOptions o;
  o.sets = {{0, 0.001}};
  Point at(0, 0);
  EXPECT_NO_THROW(fill_contours(big, o, at));  // 100 000 lines: large, but a real job
  const FillRegion r = make_fill_region(big, FillRule::non_zero, 0.0005);
  EXPECT_THROW(hatch_pieces(r.area, HatchFrame{{0, 0}, 0, 0.001}, 0, 50'000), InputError);
}

}  // namespace
}  // namespace mark
