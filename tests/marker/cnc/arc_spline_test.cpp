// The arc spline: circular arcs stay arcs (split at 180°), tiny ones become lines, elliptical
// arcs become tangent-continuous biarcs within the tolerance in both directions (spline → curve
// and curve → spline), and chords on request.
#include "marker/cnc/arc_spline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/numbers.hpp"
#include "marker/cnc/element_distance.hpp"
#include "path_checks.hpp"

namespace mark::test {
namespace {

double spline_to_curve(const std::vector<Element>& spline, const Element& curve) {
  double worst = 0;
  for (const Element& e : spline)
    for (const Point& p : samples(e, 0.005)) worst = std::max(worst, distance_to_element(p, curve));
  return worst;
}

double curve_to_spline(const std::vector<Element>& spline, const Element& curve) {
  NearSet set;
  for (const Element& e : spline) set.add(e);
  double worst = 0;
  for (const Point& p : samples(curve, 0.005)) worst = std::max(worst, set.distance(p, 1.0));
  return worst;
}

void expect_connected(const std::vector<Element>& spline, const Element& curve) {
  ASSERT_FALSE(spline.empty());
  EXPECT_LT((spline.front().start() - curve.start()).norm(), 1e-9);
  EXPECT_LT((spline.back().end() - curve.end()).norm(), 1e-9);
  for (std::size_t k = 1; k < spline.size(); ++k)
    EXPECT_LT((spline[k].start() - spline[k - 1].end()).norm(), 1e-9);
}

TEST(ArcSpline, CircularArcsStayArcsSplitAt180Degrees) {
  const Element full = Element::arc({1, 2}, 3, 0.3, 2 * kPi);
  const std::vector<Element> s = arc_spline(full, {});
  ASSERT_EQ(s.size(), 2u);
  for (const Element& e : s) {
    ASSERT_EQ(e.kind(), ElementKind::arc);
    EXPECT_NEAR(std::abs(std::get<CircularArc>(e.geometry()).sweep), kPi, 1e-12);
  }
  expect_connected(s, full);
  const Element cw = Element::arc({0, 0}, 2, 1, -3.5);
  const std::vector<Element> s2 = arc_spline(cw, {});
  ASSERT_EQ(s2.size(), 2u);
  EXPECT_LT(std::get<CircularArc>(s2[0].geometry()).sweep, 0);
  expect_connected(s2, cw);
}

TEST(ArcSpline, TinyArcsBecomeLines) {
  const std::vector<Element> a = arc_spline(Element::arc({0, 0}, 0.004, 0, 2.0), {});
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].kind(), ElementKind::line);  // chord 0.0067 mm < 0.01 mm
  const std::vector<Element> b = arc_spline(Element::arc({0, 0}, 50, 0, 0.005), {});
  EXPECT_EQ(b[0].kind(), ElementKind::line);  // bows 0.16 µm from its chord
  const std::vector<Element> c = arc_spline(Element::arc({0, 0}, 1, 0, 0.2), {});
  EXPECT_EQ(c[0].kind(), ElementKind::arc);
}

struct EllipseCase {
  double rx, ry, rotation, start, sweep;
};

TEST(ArcSpline, EllipsesBecomeBiarcsWithinTolerance) {
  const EllipseCase cases[] = {{2, 1, 0, 0, 2 * kPi},     {2, 1.9, 0.4, 1, -2 * kPi},
                               {5, 0.5, -0.3, 0.2, 2.5},  {1.0353, 0.9659, 0.7, -1, 4},
                               {3, 1, 1.2, 2, -1.3},      {0.3, 0.1, 0, 0, 2 * kPi},
                               {10, 7, 2, -0.5, 0.4}};
  for (double tol : {0.005, 0.001}) {
    for (const EllipseCase& c : cases) {
      const Element e = Element::ellipse({1, -1}, c.rx, c.ry, c.rotation, c.start, c.sweep);
      ArcSplineOptions o;
      o.tolerance_mm = tol;
      const std::vector<Element> s = arc_spline(e, o);
      SCOPED_TRACE(testing::Message() << "rx " << c.rx << " ry " << c.ry << " sweep " << c.sweep << " tol " << tol);
      expect_connected(s, e);
      EXPECT_LE(spline_to_curve(s, e), tol);
      EXPECT_LE(curve_to_spline(s, e), tol);
      double len = 0;
      for (const Element& a : s) {
        EXPECT_NE(a.kind(), ElementKind::ellipse);
        if (a.kind() == ElementKind::arc) {
          EXPECT_LE(std::abs(std::get<CircularArc>(a.geometry()).sweep), kPi + 1e-12);
        }
        len += a.length();
      }
      EXPECT_NEAR(len, e.length(), 0.01 * e.length());
      // Tangent continuity where arcs meet (biarcs join smoothly; arcs too small for a
      // controller become chords, which turn at their joints).
      for (std::size_t k = 1; k < s.size(); ++k)
        if (s[k].kind() == ElementKind::arc && s[k - 1].kind() == ElementKind::arc) {
          EXPECT_GT(s[k].tangent_at(0).dot(s[k - 1].tangent_at(1)), 0.999);
        }
    }
  }
}

TEST(ArcSpline, ChordsOnRequest) {
  const Element e = Element::ellipse({0, 0}, 3, 1, 0.2, 0, 2 * kPi);
  ArcSplineOptions o;
  o.ellipse_chords = true;
  const std::vector<Element> s = arc_spline(e, o);
  for (const Element& a : s) EXPECT_EQ(a.kind(), ElementKind::line);
  EXPECT_LE(spline_to_curve(s, e), 0.005);
  EXPECT_LE(curve_to_spline(s, e), 0.005);
  expect_connected(s, e);
}

}  // namespace
}  // namespace mark::test
