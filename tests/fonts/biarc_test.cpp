// Biarc fitter: arcs stay within the tolerance of the Bézier both ways, near-circles give few arcs
// of the circle's radius, S-curves split at the inflection, straight and degenerate cubics.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fonts/biarc.hpp"

namespace mark {
namespace {

// Hausdorff-style check by dense sampling: every fitted point near the curve (exact-ish curve
// distance) and every curve point near the fit (exact distance to lines/arcs).
double two_way_error(const CubicBezier& c, const std::vector<Element>& fit) {
  double worst = 0;
  for (int i = 0; i <= 2000; ++i) {
    const Point p = c.point_at(i / 2000.0);
    double best = INFINITY;
    for (const Element& e : fit) best = std::min(best, distance_to_element(e, p));
    worst = std::max(worst, best);
  }
  for (const Element& e : fit)
    for (int j = 0; j <= 50; ++j) worst = std::max(worst, distance_to_cubic(c, e.point_at(j / 50.0)));
  return worst;
}

void expect_chained(const CubicBezier& c, const std::vector<Element>& fit) {
  ASSERT_FALSE(fit.empty());
  EXPECT_NEAR((fit.front().start() - c.p0).norm(), 0, 1e-9);
  EXPECT_NEAR((fit.back().end() - c.p3).norm(), 0, 1e-9);
  for (std::size_t i = 1; i < fit.size(); ++i) {
    EXPECT_NEAR((fit[i].start() - fit[i - 1].end()).norm(), 0, 1e-9) << "gap before element " << i;
    // Biarcs are tangent-continuous (G1) at every join.
    EXPECT_NEAR((fit[i].tangent_at(0) - fit[i - 1].tangent_at(1)).norm(), 0, 1e-6) << i;
  }
}

TEST(Biarc, QuarterCircleCubicFitsWithFewArcsOfTheCircleRadius) {
  // The 0.5523 cubic strays 0.027 % from its circle (0.027 at r = 100). Above that tolerance the
  // biarc is the circle itself: two arcs of radius 100 about the origin.
  const double r = 100, k = 0.5523 * r;
  const CubicBezier c{{r, 0}, {r, k}, {k, r}, {0, r}};
  for (const double tol : {0.05, 0.01}) {
    std::vector<Element> fit;
    fit_biarcs(c, tol, fit);
    expect_chained(c, fit);
    EXPECT_LE(fit.size(), tol > 0.03 ? 2u : 8u) << tol;
    for (const Element& e : fit) {
      ASSERT_EQ(e.kind(), ElementKind::arc);
      const auto& a = std::get<CircularArc>(e.geometry());
      // Below 0.027 the arcs follow the cubic's own curvature, which varies by about 1 %.
      EXPECT_NEAR(a.radius, r, tol > 0.03 ? 1e-9 : 1.5) << tol;
      EXPECT_NEAR(a.center.norm(), 0, tol > 0.03 ? 1e-9 : 1.5) << tol;
      EXPECT_GT(a.sweep, 0);  // counter-clockwise like the curve
    }
    EXPECT_LE(two_way_error(c, fit), tol + 1e-9) << tol;
  }
}

TEST(Biarc, TighterToleranceStillHoldsAndNeedsMoreArcs) {
  const CubicBezier c{{0, 0}, {30, 90}, {120, 100}, {150, 20}};
  std::vector<Element> coarse, fine;
  fit_biarcs(c, 0.5, coarse);
  fit_biarcs(c, 0.001, fine);
  expect_chained(c, coarse);
  expect_chained(c, fine);
  EXPECT_LE(two_way_error(c, coarse), 0.5 + 1e-9);
  EXPECT_LE(two_way_error(c, fine), 0.001 + 1e-9);
  EXPECT_GT(fine.size(), coarse.size());
}

TEST(Biarc, SCurveSplitsAtItsInflection) {
  const CubicBezier c{{0, 0}, {50, 100}, {50, -100}, {100, 0}};
  const auto t = inflections(c);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_NEAR(t[0], 0.5, 1e-12);
  std::vector<Element> fit;
  const double tol = 0.05;
  fit_biarcs(c, tol, fit);
  expect_chained(c, fit);
  EXPECT_LE(two_way_error(c, fit), tol + 1e-9);
  // Some element ends exactly at the inflection point; arcs before it turn one way, after it the
  // other way.
  const Point mid = c.point_at(0.5);
  std::size_t split = fit.size();
  for (std::size_t i = 0; i < fit.size(); ++i)
    if ((fit[i].end() - mid).norm() < 1e-9) split = i + 1;
  ASSERT_LT(split, fit.size());
  for (std::size_t i = 0; i < fit.size(); ++i) {
    if (fit[i].kind() != ElementKind::arc) continue;
    const double sweep = std::get<CircularArc>(fit[i].geometry()).sweep;
    if (i < split)
      EXPECT_LT(sweep, 0) << i;  // leaves upwards, turns clockwise
    else
      EXPECT_GT(sweep, 0) << i;
  }
}

TEST(Biarc, ConvexCubicHasNoInflection) {
  EXPECT_TRUE(inflections(CubicBezier{{0, 0}, {0, 50}, {50, 100}, {100, 100}}).empty());
}

TEST(Biarc, StraightCubicBecomesLinesAndPointCubicNothing) {
  std::vector<Element> fit;
  fit_biarcs(CubicBezier{{0, 0}, {10, 5}, {20, 10}, {30, 15}}, 1e-3, fit);
  ASSERT_FALSE(fit.empty());
  for (const Element& e : fit) EXPECT_EQ(e.kind(), ElementKind::line);
  EXPECT_NEAR((fit.back().end() - Point(30, 15)).norm(), 0, 1e-12);
  fit.clear();
  fit_biarcs(CubicBezier{{7, 7}, {7, 7}, {7, 7}, {7, 7}}, 1e-3, fit);
  EXPECT_TRUE(fit.empty());
}

TEST(Biarc, QuadraticElevationIsExact) {
  const Point a(0, 0), k(50, 100), b(100, 0);
  const CubicBezier c = CubicBezier::from_quadratic(a, k, b);
  for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
    const Point q = (1 - t) * (1 - t) * a + 2 * (1 - t) * t * k + t * t * b;
    EXPECT_NEAR((c.point_at(t) - q).norm(), 0, 1e-12);
  }
}

TEST(Biarc, ZeroLengthTangentHandleUsesTheNextControlPoint) {
  // p1 == p0: the start tangent comes from p2.
  const CubicBezier c{{0, 0}, {0, 0}, {100, 100}, {200, 0}};
  std::vector<Element> fit;
  fit_biarcs(c, 0.01, fit);
  expect_chained(c, fit);
  EXPECT_LE(two_way_error(c, fit), 0.01 + 1e-9);
}

}  // namespace
}  // namespace mark
