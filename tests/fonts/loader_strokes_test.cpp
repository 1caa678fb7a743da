// Stroke assembly shared by the loaders: pieces join where their ends meet, in file order, with
// laser-off moves only where the pen really has to move.
#include <gtest/gtest.h>

#include "fonts/loaders/strokes.hpp"
#include "loader_test_util.hpp"

namespace mark::loaders {
namespace {

using test::expect_point;

// A glyph with one piece per polyline given as x0,y0,x1,y1,...
RawGlyph pieces(std::initializer_list<std::vector<double>> polylines) {
  RawGlyph g;
  for (const auto& p : polylines) {
    for (std::size_t i = 2; i + 1 < p.size(); i += 2)
      g.elements.push_back(Element::line({p[i - 2], p[i - 1]}, {p[i], p[i + 1]}));
    g.end_piece();
  }
  return g;
}

std::vector<Point> path_of(const std::vector<Element>& elements,
                           std::vector<bool>* laser = nullptr) {
  std::vector<Point> pts;
  if (elements.empty()) return pts;
  pts.push_back(elements.front().start());
  for (const Element& e : elements) {
    EXPECT_LE((e.start() - pts.back()).norm(), 1e-9);
    pts.push_back(e.end());
    if (laser) laser->push_back(e.laser());
  }
  return pts;
}

TEST(AssembleStrokes, AppendsAPieceStartingWhereTheStrokeEnds) {
  const auto out = assemble_strokes(pieces({{0, 0, 1, 0}, {1, 0, 1, 1}}), 1e-9);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_TRUE(out[0].laser() && out[1].laser());
  expect_point(out[1].end(), 1, 1);
}

TEST(AssembleStrokes, ReversesAPieceEndingWhereTheStrokeEnds) {
  const auto out = assemble_strokes(pieces({{0, 0, 1, 0}, {1, 1, 2, 1, 1, 0}}), 1e-9);
  std::vector<bool> laser;
  const auto pts = path_of(out, &laser);
  ASSERT_EQ(pts.size(), 4u);
  expect_point(pts[2], 2, 1);
  expect_point(pts[3], 1, 1);
  EXPECT_EQ(laser, (std::vector<bool>{true, true, true}));
}

TEST(AssembleStrokes, PrependsAPieceEndingWhereTheStrokeStarts) {
  const auto out = assemble_strokes(pieces({{1, 0, 2, 0}, {0, 0, 1, 0}}), 1e-9);
  const auto pts = path_of(out);
  ASSERT_EQ(pts.size(), 3u);
  expect_point(pts[0], 0, 0);
  expect_point(pts[2], 2, 0);
}

TEST(AssembleStrokes, ReversesTheStrokeWhenBothStartTogether) {
  // The Hershey 'A': two legs from the apex become one stroke over it.
  const auto out = assemble_strokes(pieces({{9, 21, 1, 0}, {9, 21, 17, 0}}), 1e-9);
  const auto pts = path_of(out);
  ASSERT_EQ(pts.size(), 3u);
  expect_point(pts[0], 1, 0);
  expect_point(pts[1], 9, 21);
  expect_point(pts[2], 17, 0);
}

TEST(AssembleStrokes, MovesWithTheLaserOffBetweenStrokes) {
  const auto out = assemble_strokes(pieces({{0, 0, 1, 0}, {5, 5, 6, 5}, {6, 5, 6, 6}}), 1e-9);
  std::vector<bool> laser;
  const auto pts = path_of(out, &laser);
  EXPECT_EQ(laser, (std::vector<bool>{true, false, true, true}));
  expect_point(out[1].start(), 1, 0);
  expect_point(out[1].end(), 5, 5);
}

TEST(AssembleStrokes, JoinsWithinTheToleranceOnly) {
  const double tol = 1e-9;
  const auto joined = assemble_strokes(pieces({{0, 0, 1, 0}, {1 + 0.9e-9, 0, 2, 0}}), tol);
  EXPECT_EQ(joined.size(), 2u);
  const auto apart = assemble_strokes(pieces({{0, 0, 1, 0}, {1 + 2e-9, 0, 2, 0}}), tol);
  ASSERT_EQ(apart.size(), 3u);
  EXPECT_FALSE(apart[1].laser());
}

TEST(AssembleStrokes, DropsRepeatedPointsAndEmptyPieces) {
  const auto out =
      assemble_strokes(pieces({{0, 0, 0, 0, 1, 0, 1, 0}, {3, 3, 3, 3}, {1, 0, 2, 0}}), 1e-9);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_TRUE(out[0].laser() && out[1].laser());
  expect_point(out[1].end(), 2, 0);
  EXPECT_TRUE(assemble_strokes(pieces({{3, 3, 3, 3}}), 1e-9).empty());
}

TEST(AssembleStrokes, NoMoveWhenAGrownStrokeMeetsThePreviousOne) {
  // Stroke 1 ends at (0,6); piece 3 is prepended to stroke 2 and now starts there too.
  const auto out = assemble_strokes(pieces({{0, 0, 0, 6}, {2, 6, 2, 3}, {0, 6, 2, 6}}), 1e-9);
  std::vector<bool> laser;
  path_of(out, &laser);
  EXPECT_EQ(laser, (std::vector<bool>{true, true, true}));
}

TEST(AssembleStrokes, ClosedArcsKeepTheirGeometryWhenReversed) {
  RawGlyph g;
  g.elements.push_back(Element::line({0, 0}, {2, 0}));
  g.end_piece();
  g.elements.push_back(Element::arc({1, 0}, 1, 0, std::numbers::pi / 2));  // (2,0) → (1,1)
  g.end_piece();
  g.elements.push_back(
      Element::arc({1, 2}, 1, -std::numbers::pi / 2, -std::numbers::pi / 2));  // (1,1) → (0,2)
  g.end_piece();
  const auto out = assemble_strokes(g, 1e-9);
  ASSERT_EQ(out.size(), 3u);
  expect_point(out[2].end(), 0, 2);
  expect_point(out[1].point_at(0.5), 1 + std::sqrt(0.5), std::sqrt(0.5));
}

}  // namespace
}  // namespace mark::loaders
