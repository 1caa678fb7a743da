// Red-pointer framing outlines: the box is the lit bounds, the hull is convex, closed and holds
// every lit point, the strokes follow the glyphs within the flattening tolerance.
#include <gtest/gtest.h>

#include "base/error.hpp"
#include "fonts/catalog.hpp"
#include "marker/frame/frame_paths.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/layout/layout.hpp"

namespace mark {
namespace {

Figure text(const std::string& s, double angle_deg = 0) {
  LayoutOptions o;
  o.height_mm = 4;
  o.angle_deg = angle_deg;
  return layout_text(s, *open_font(kBuiltinFontName), o);
}

double cross(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

TEST(FramePaths, BoxIsTheLitBounds) {
  const Figure f = text("SN 42");
  const auto paths = frame_paths(f, FrameShape::box);
  ASSERT_EQ(paths.size(), 1u);
  ASSERT_EQ(paths[0].size(), 5u);
  const Box b = f.bounds();
  EXPECT_DOUBLE_EQ(paths[0][0].x, b.min.x());
  EXPECT_DOUBLE_EQ(paths[0][2].x, b.max.x());
  EXPECT_DOUBLE_EQ(paths[0][2].y, b.max.y());
  EXPECT_DOUBLE_EQ(paths[0][4].x, paths[0][0].x);
  EXPECT_DOUBLE_EQ(paths[0][4].y, paths[0][0].y);
}

TEST(FramePaths, HullIsConvexClosedAndHoldsEveryLitPoint) {
  const Figure f = text("SN 42", 30);  // inclined: the hull is tighter than the box
  const auto hull = frame_paths(f, FrameShape::hull).at(0);
  ASSERT_GE(hull.size(), 4u);
  EXPECT_DOUBLE_EQ(hull.front().x, hull.back().x);
  EXPECT_DOUBLE_EQ(hull.front().y, hull.back().y);
  for (std::size_t i = 2; i < hull.size(); ++i)
    EXPECT_GT(cross(hull[i - 2], hull[i - 1], hull[i]), 0) << "not convex (counter-clockwise) at " << i;
  for (const auto& line : intended_polylines(f, 0.01))
    for (const Vec2& p : line)
      for (std::size_t i = 1; i < hull.size(); ++i)
        ASSERT_GE(cross(hull[i - 1], hull[i], p), -0.02 * norm(hull[i] - hull[i - 1]))
            << "(" << p.x << ", " << p.y << ") outside edge " << i;
}

TEST(FramePaths, StrokesFollowTheGlyphs) {
  const Figure f = text("O8");
  const auto strokes = frame_paths(f, FrameShape::strokes, 0.02);
  EXPECT_GE(strokes.size(), 2u);
  const auto intended = intended_polylines(f, 0.005);
  for (const auto& s : strokes)
    for (const Vec2& p : s) {
      double best = 1e9;
      for (const auto& l : intended)
        for (const Vec2& q : l) best = std::min(best, norm(p - q));
      EXPECT_LT(best, 0.006);  // vertices on the curves (within the sampling)
    }
  EXPECT_EQ(parse_frame_shape("hull"), FrameShape::hull);
  EXPECT_THROW(parse_frame_shape("circle"), InputError);
  EXPECT_THROW(frame_paths(text(" "), FrameShape::box), InputError);
}

}  // namespace
}  // namespace mark
