// The shared join rule (fonts/stroke_join.hpp): ends within the fraction of the letter height
// are one point at every height; chaining joins pieces across the drawing order, keeps lone
// points and drops repeated ones; QCAD's normal.cxf, whose arcs miss their neighbours, chains
// into the same strokes at 1 mm and at 1 m, and with the old absolute tolerance it did not.
#include "fonts/stroke_join.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "base/numbers.hpp"
#include "fonts/loaders.hpp"
#include "loader_test_util.hpp"

namespace mark {
namespace {

// An 'O' of radius r drawn as two halves, the second starting `miss` away from where the first
// ended, and drawn in the other direction.
std::vector<Element> two_halves(double r, double miss) {
  return {Element::arc({0, 0}, r, 0, kPi), Element::line({r, 0}, {-r, 0}, false),
          Element::arc({0, -miss}, r, kPi, kPi)};
}

TEST(StrokeJoin, PiecesThatMissByLessThanTheFractionAreOneStroke) {
  for (double height : {1.0, 10.0, 1000.0}) {
    const double r = height / 2, tol = join_tolerance(height);
    const auto joined = chain_strokes(two_halves(r, 0.5 * tol), tol);
    ASSERT_EQ(joined.size(), 1u) << height;
    EXPECT_TRUE(joined.front().closed(tol));
    EXPECT_EQ(joined.front().elements.size(), 2u);
    // Ten times the tolerance apart: two strokes.
    EXPECT_EQ(chain_strokes(two_halves(r, 10 * tol), tol).size(), 2u) << height;
  }
}

TEST(StrokeJoin, PointsStayAloneAndRepeatedOnesGo) {
  const double tol = 1e-4;
  // A dot on its own, a repeated point at a stroke's end, the same dot twice.
  const std::vector<Element> e = {Element::line({5, 5}, {5, 5}), Element::line({5, 5}, {6, 6}, false),
                                  Element::line({0, 0}, {1, 0}), Element::line({1, 0}, {1, 0}),
                                  Element::line({1, 0}, {5, 5}, false), Element::line({5, 5}, {5, 5})};
  const auto s = chain_strokes(e, tol);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].elements.size(), 1u);  // the dot
  EXPECT_EQ(s[0].start(), Point(5, 5));
  EXPECT_EQ(s[1].elements.size(), 1u);  // the line, without its repeated end point
}

TEST(StrokeJoin, NormalCxfChainsTheSameAtEveryHeight) {
  const StrokeFont font = load_font_file(test::kDataDir + "/normal.cxf");
  const double cap = font.metrics().cap_height;
  ASSERT_NEAR(cap, 9, 1e-9);
  std::size_t with_fraction = 0, with_absolute = 0;
  for (const char c : std::string("0s?y")) {
    const Glyph& g = font.glyph(static_cast<char32_t>(c));
    std::size_t strokes = 0;
    for (double height_mm : {1.0, 10.0, 1000.0}) {
      const double scale = height_mm / cap;
      std::vector<Element> scaled;
      for (const Element& e : g.elements) scaled.push_back(e.transformed(Affine(Eigen::Scaling(scale))));
      const std::size_t n = chain_strokes(scaled, join_tolerance(height_mm)).size();
      if (height_mm == 1.0) {
        strokes = n;
        with_fraction += n;
        // The old rule at 1 mm: ends closer than 1e-6 mm.
        with_absolute += chain_strokes(scaled, 1e-6).size();
      }
      EXPECT_EQ(n, strokes) << c << " at " << height_mm << " mm";
    }
  }
  // '0', 's', '?' and 'y' miss their own joins by 2.4e-5 to 2.7e-5 of the height: the absolute
  // tolerance cut them into more strokes, each one more lift of the cutter.
  EXPECT_LT(with_fraction, with_absolute);
}

}  // namespace
}  // namespace mark
