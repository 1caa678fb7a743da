// Stroke order: glyph order by default; `shortest` (nearest neighbour with reversal, then 2-opt)
// shortens the jumps on a known case and keeps every stroke exactly once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "marker/plan/plan.hpp"
#include "marker/plan/stroke_order.hpp"
#include "tests/marker/plan_test_support.hpp"

namespace mark {
namespace {

// Each stroke as its unordered end-point pair (rounded), for "same strokes" comparisons.
std::vector<std::pair<std::pair<long, long>, std::pair<long, long>>> keys(const std::vector<Stroke>& s) {
  std::vector<std::pair<std::pair<long, long>, std::pair<long, long>>> k;
  auto q = [](const Point& p) { return std::pair<long, long>(std::lround(p.x() * 1e6), std::lround(p.y() * 1e6)); };
  for (const Stroke& x : s) {
    auto a = q(x.start()), b = q(x.end());
    k.push_back(a < b ? std::pair(a, b) : std::pair(b, a));
  }
  std::sort(k.begin(), k.end());
  return k;
}

// Strokes alternating between two rows 10 mm apart, every second one drawn right to left: in
// glyph order the pen zigzags; the best order does one row, then the other, reversing strokes.
std::vector<Stroke> zigzag_rows() {
  std::vector<Stroke> s;
  for (int i = 0; i < 10; ++i) {
    const double y = (i % 2) ? 10 : 0, x = i;
    Stroke st;
    st.elements.push_back(i % 3 == 0 ? Element::line({x + 0.8, y}, {x, y}) : Element::line({x, y}, {x + 0.8, y}));
    s.push_back(st);
  }
  return s;
}

TEST(StrokeOrder, GlyphOrderIsKept) {
  const auto s = zigzag_rows();
  const auto o = order_strokes(s, StrokeOrder::glyph, {0, 0});
  ASSERT_EQ(o.size(), s.size());
  for (std::size_t i = 0; i < s.size(); ++i) EXPECT_EQ(o[i].start(), s[i].start());
}

TEST(StrokeOrder, ShortestReducesJumpsAndKeepsEveryStrokeOnce) {
  const auto s = zigzag_rows();
  const Point home(0, 0);
  const double before = jump_length_mm(s, home);
  const auto o = order_strokes(s, StrokeOrder::shortest, home);
  const double after = jump_length_mm(o, home);
  EXPECT_NEAR(before, 91.105, 0.001);  // nine row changes of ≥ 10 mm
  // The optimum: the bottom row left to right (four 1.2 mm gaps), across to (9.8, 10) — 10.05 mm
  // — and the top row back right to left, its strokes reversed: 4.8 + 10.05 + 4.8 = 19.65 mm.
  EXPECT_NEAR(after, 4 * 1.2 + std::hypot(1.0, 10.0) + 4 * 1.2, 1e-9);
  EXPECT_EQ(keys(o), keys(s));
}

TEST(StrokeOrder, RandomStrokesNeverGetLongerAndStayComplete) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-20, 20);
  std::vector<Stroke> s;
  for (int i = 0; i < 120; ++i) {
    Stroke st;
    const Point a(u(rng), u(rng));
    st.elements.push_back(Element::line(a, a + Point(0.5, 0.2)));
    if (i % 4 == 0) st.elements.push_back(Element::line(a + Point(0.5, 0.2), a + Point(0.5, 1)));
    s.push_back(st);
  }
  const auto o = order_strokes(s, StrokeOrder::shortest, {0, 0});
  EXPECT_LT(jump_length_mm(o, {0, 0}), 0.25 * jump_length_mm(s, {0, 0}));
  EXPECT_EQ(keys(o), keys(s));
  for (const Stroke& x : o)  // a reversed stroke is still continuous
    for (std::size_t i = 1; i < x.elements.size(); ++i)
      EXPECT_NEAR((x.elements[i - 1].end() - x.elements[i].start()).norm(), 0, 1e-12);
}

TEST(StrokeOrder, PlanReportsJumpLengthEitherWay) {
  Figure f = test::figure_of({{Element::line({0, 0}, {1, 0})}, {Element::line({5, 0}, {6, 0})},
                              {Element::line({2, 0}, {3, 0})}});
  const Pen pen = default_pen(CornerStrategy::none, 0.12e-3, 500, 5000);
  EXPECT_NEAR(plan_figure(f, pen, StrokeOrder::glyph).jump_length_mm, 4 + 4, 1e-12);
  EXPECT_NEAR(plan_figure(f, pen, StrokeOrder::shortest).jump_length_mm, 1 + 2, 1e-12);
}

}  // namespace
}  // namespace mark
