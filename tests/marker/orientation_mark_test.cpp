// The frame's orientation mark: an upright F beside the job at its +x side, on the left where
// the right leaves the field, inside where neither side has room; always inside the field.
#include <gtest/gtest.h>

#include "base/error.hpp"
#include "marker/frame/orientation_mark.hpp"

namespace mark {
namespace {

Box box(double x0, double y0, double x1, double y1) {
  Box b;
  b.add(Point(x0, y0));
  b.add(Point(x1, y1));
  return b;
}

Box bounds_of(const std::vector<Vec2>& path) {
  Box b;
  for (const Vec2& p : path) b.add(Point(p.x, p.y));
  return b;
}

TEST(OrientationMark, AnUprightFAtTheJobsPlusXSide) {
  const std::vector<Vec2> f = orientation_mark(box(-10, -2, 10, 2), 110);
  ASSERT_EQ(f.size(), 6u);
  const double h = 4;  // as tall as the job (2..10 mm)
  // Foot, top of the stem, top bar's end, back, middle, middle bar's end.
  EXPECT_DOUBLE_EQ(f[0].x, 10 + h / 2);  // half its height to the right of the job
  EXPECT_DOUBLE_EQ(f[0].y, -2);
  EXPECT_DOUBLE_EQ(f[1].x, f[0].x);
  EXPECT_DOUBLE_EQ(f[1].y, 2);
  EXPECT_DOUBLE_EQ(f[2].x - f[1].x, 0.6 * h);  // the top bar points to +x
  EXPECT_DOUBLE_EQ(f[2].y, f[1].y);
  EXPECT_DOUBLE_EQ(f[4].y - f[0].y, 0.55 * h);  // the middle bar below the top
  EXPECT_DOUBLE_EQ(f[5].x - f[4].x, 0.45 * h);
  // Small and large jobs: 2 to 10 mm.
  EXPECT_DOUBLE_EQ(bounds_of(orientation_mark(box(0, 0, 5, 0.5), 110)).height(), 2);
  EXPECT_DOUBLE_EQ(bounds_of(orientation_mark(box(-20, -20, 20, 20), 110)).height(), 10);
}

TEST(OrientationMark, LeftWhenTheRightLeavesTheFieldInsideWhenNeitherFits) {
  const std::vector<Vec2> left = orientation_mark(box(40, 0, 54, 3), 110);
  EXPECT_LT(bounds_of(left).max.x(), 40);
  const Box wide = box(-54, -1, 54, 1);
  const Box inside = bounds_of(orientation_mark(wide, 110));
  EXPECT_GE(inside.min.x(), -55);
  EXPECT_LE(inside.max.x(), 55);
  EXPECT_NEAR(inside.center().x(), 0, 1e-9);
  // Near the top of the field: kept inside it.
  const Box top = bounds_of(orientation_mark(box(0, 53, 10, 54.9), 110));
  EXPECT_LE(top.max.y(), 55);
  EXPECT_THROW(orientation_mark(Box{}, 110), InputError);
}

}  // namespace
}  // namespace mark
