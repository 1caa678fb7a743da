// Raised letters that run into each other: two upright strokes 5 mm long, d apart, raised to a
// width w, share a strip (w − d) × 5 mm plus the lens where their round ends overlap — nothing at
// all when d ≥ w. Only neighbours that touch are reported, each pair once.
#include "marker/cnc/letter_contacts.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mark {
namespace {

Figure bars(const std::vector<double>& xs) {
  Figure f;
  for (double x : xs) {
    PlacedGlyph g;
    g.code_point = U'I';
    g.elements.push_back(Element::line(Point(x, 0), Point(x, 5)));
    f.glyphs.push_back(g);
  }
  return f;
}

// Area shared by two discs of radius r whose centres are d apart.
double lens(double r, double d) {
  if (d >= 2 * r) return 0;
  return 2 * r * r * std::acos(d / (2 * r)) - d / 2 * std::sqrt(4 * r * r - d * d);
}

TEST(LetterContacts, SharedAreaOfTwoRaisedStrokes) {
  const double w = 1.0;
  for (double d : {0.2, 0.5, 0.9}) {
    const std::vector<LetterContact> c = touching_letters(bars({0, d}), w);
    ASSERT_EQ(c.size(), 1u) << d;
    EXPECT_EQ(c[0].first, 0u);
    EXPECT_EQ(c[0].second, 1u);
    const double expected = (w - d) * 5 + lens(w / 2, d);
    EXPECT_NEAR(c[0].area_mm2, expected, 0.005 * expected + 1e-4) << d;
    EXPECT_NEAR(c[0].at.x(), d / 2, 1e-3);
    EXPECT_NEAR(c[0].at.y(), 2.5, 1e-3);
  }
}

TEST(LetterContacts, ApartOrFarAwayIsNoContact) {
  EXPECT_TRUE(touching_letters(bars({0, 1.01}), 1.0).empty());
  EXPECT_TRUE(touching_letters(bars({0, 3}), 1.0).empty());
  // Three in a row 0.8 apart: the neighbours touch, the outer two (1.6 apart) do not.
  const std::vector<LetterContact> c = touching_letters(bars({0, 0.8, 1.6}), 1.0);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].first, 0u);
  EXPECT_EQ(c[0].second, 1u);
  EXPECT_EQ(c[1].first, 1u);
  EXPECT_EQ(c[1].second, 2u);
}

}  // namespace
}  // namespace mark
