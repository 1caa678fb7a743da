// The narrowest gap between strokes, on figures whose gaps are known by construction: parallel
// strokes, a dot above a stem, the inside of a ring; and the places that are not gaps — strokes
// that cross or meet at a T, the apex of a V, the wedge where two strokes touch tangentially.
#include "marker/cnc/stroke_gaps.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace mark {
namespace {

Figure figure_of(std::vector<Element> elements, double height_mm = 10) {
  Figure f;
  PlacedGlyph g;
  g.elements = std::move(elements);
  f.glyphs.push_back(std::move(g));
  f.letter_height_mm = height_mm;
  return f;
}

TEST(StrokeGaps, ParallelStrokesAreTheirDistanceApart) {
  const Figure f = figure_of({Element::line({0, 0}, {0, 10}), Element::line({0.7, 0}, {0.7, 10}),
                              Element::line({3, 0}, {3, 10})});
  const auto g = narrowest_stroke_gap(f, 1.0);
  ASSERT_TRUE(g);
  EXPECT_NEAR(g->width_mm, 0.7, 1e-9);
  EXPECT_NEAR(g->a.x() + g->b.x(), 0.7, 1e-9);  // one point on each stroke
  // A tool narrower than every gap: nothing to report.
  EXPECT_FALSE(narrowest_stroke_gap(f, 0.69));
}

TEST(StrokeGaps, TheDotAboveAStemIsAGapFromTheStemsTip) {
  // An 'i': the stem from 0 to 6, the dot (a point) at 7.
  const Figure f = figure_of({Element::line({0, 0}, {0, 6}), Element::line({0, 6}, {0, 7}, false),
                              Element::line({0, 7}, {0, 7})});
  const auto g = narrowest_stroke_gap(f, 5);
  ASSERT_TRUE(g);
  EXPECT_NEAR(g->width_mm, 1.0, 1e-9);
}

TEST(StrokeGaps, TheInsideOfARingIsItsDiameter) {
  // One closed stroke: its opposite sides face each other across the diameter.
  const Figure f = figure_of({Element::arc({0, 0}, 1.5, 0, 2 * std::numbers::pi)});
  const auto g = narrowest_stroke_gap(f, 10);
  ASSERT_TRUE(g);
  EXPECT_NEAR(g->width_mm, 3.0, 1e-2);  // flattened within 1e-3 of the height for the search
}

TEST(StrokeGaps, CrossingsTeesVeesAndTangentsAreNoGaps) {
  // A cross, a T (the stem ends on the bar), a V (one stroke), and an arc leaving a line
  // tangentially (a 'B' bowl and its crossbar): a wide tool fills their corners, which is the
  // letter, not two grooves merging.
  const Figure f = figure_of({Element::line({0, 0}, {4, 4}), Element::line({0, 4}, {4, 0}),
                              Element::line({10, 4}, {14, 4}), Element::line({12, 4}, {12, 0}),
                              Element::line({20, 4}, {22, 0}), Element::line({22, 0}, {24, 4}),
                              Element::line({30, 0}, {36, 0}), Element::arc({30, 2}, 2, -std::numbers::pi / 2, std::numbers::pi / 2)});
  EXPECT_FALSE(narrowest_stroke_gap(f, 1.0));
}

TEST(StrokeGaps, TouchingWithinAFontsRoundingIsNoGap) {
  // A T whose stem misses the bar by 0.3 % of the height: no tool can tell.
  const Figure f = figure_of({Element::line({0, 4}, {4, 4}), Element::line({2, 3.97}, {2, 0})});
  EXPECT_FALSE(narrowest_stroke_gap(f, 1.0));
  const Figure apart = figure_of({Element::line({0, 4}, {4, 4}), Element::line({2, 3.7}, {2, 0})});
  const auto g = narrowest_stroke_gap(apart, 1.0);
  ASSERT_TRUE(g);
  EXPECT_NEAR(g->width_mm, 0.3, 1e-9);
}

}  // namespace
}  // namespace mark
