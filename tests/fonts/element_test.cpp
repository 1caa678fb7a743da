// Exact element geometry: evaluation, length, bounds, reversal, and transforms that keep arcs
// exact (circular under similarities, elliptical otherwise).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/error.hpp"
#include "base/numbers.hpp"
#include "fonts/element.hpp"

namespace mark {
namespace {

void expect_near(const Point& a, const Point& b, double tol) {
  EXPECT_NEAR(a.x(), b.x(), tol);
  EXPECT_NEAR(a.y(), b.y(), tol);
}

Affine make_affine(double a, double b, double c, double d, double tx, double ty) {
  Affine t = Affine::Identity();
  t.linear() << a, b, c, d;
  t.translation() << tx, ty;
  return t;
}

TEST(Element, LinePointTangentLength) {
  const Element l = Element::line({1, 2}, {4, 6});
  expect_near(l.point_at(0.5), {2.5, 4}, 1e-15);
  expect_near(l.tangent_at(0.3), {0.6, 0.8}, 1e-15);
  EXPECT_DOUBLE_EQ(l.length(), 5.0);
  EXPECT_DOUBLE_EQ(l.length_between(0.2, 0.6), 2.0);
  EXPECT_EQ(l.kind(), ElementKind::line);
}

TEST(Element, ArcThroughFindsCentreOnTheRightSide) {
  // Quarter circle of radius 1 from (1,0) to (0,1), counter-clockwise: centre at the origin.
  const Element ccw = Element::arc_through({1, 0}, {0, 1}, 1.0, true);
  const auto& a = std::get<CircularArc>(ccw.geometry());
  expect_near(a.center, {0, 0}, 1e-15);
  EXPECT_NEAR(a.sweep, kPi / 2, 1e-15);
  // Clockwise minor arc between the same points has its centre at (1,1).
  const Element cw = Element::arc_through({1, 0}, {0, 1}, 1.0, false);
  expect_near(std::get<CircularArc>(cw.geometry()).center, {1, 1}, 1e-15);
  EXPECT_NEAR(std::get<CircularArc>(cw.geometry()).sweep, -kPi / 2, 1e-15);
  // Major arc counter-clockwise: centre (1,1), sweep 3π/2.
  const Element major = Element::arc_through({1, 0}, {0, 1}, 1.0, true, true);
  expect_near(std::get<CircularArc>(major.geometry()).center, {1, 1}, 1e-15);
  EXPECT_NEAR(std::get<CircularArc>(major.geometry()).sweep, 1.5 * kPi, 1e-15);
  expect_near(major.end(), {0, 1}, 1e-15);
  EXPECT_THROW(Element::arc_through({0, 0}, {3, 0}, 1.0, true), InputError);
}

TEST(Element, BulgeOneIsASemicircle) {
  const Element half = Element::bulge({0, 0}, {2, 0}, 1.0);
  const auto& a = std::get<CircularArc>(half.geometry());
  expect_near(a.center, {1, 0}, 1e-15);
  EXPECT_NEAR(a.radius, 1.0, 1e-15);
  EXPECT_NEAR(a.sweep, kPi, 1e-12);
  // Counter-clockwise from (0,0) to (2,0) passes below the chord.
  expect_near(half.point_at(0.5), {1, -1}, 1e-12);
  // tan(22.5°) with negative sign: a clockwise quarter circle.
  const Element quarter = Element::bulge({0, 0}, {1, 1}, -std::tan(kPi / 8));
  EXPECT_NEAR(std::get<CircularArc>(quarter.geometry()).sweep, -kPi / 2, 1e-12);
  EXPECT_EQ(Element::bulge({0, 0}, {1, 1}, 0).kind(), ElementKind::line);
}

TEST(Element, EllipseLengthToNineDigits) {
  // Perimeter of the ellipse with semi-axes 2 and 1: 9.688448220547675 (complete elliptic
  // integral of the second kind, 4·a·E(√3/2)).
  const Element e = Element::ellipse({0, 0}, 2, 1, 0.3, 0.1, 2 * kPi);
  EXPECT_NEAR(e.length(), 9.688448220547675, 9.688448220547675 * 1e-9);
  // A very flat ellipse tends to four times its major semi-axis.
  const Element flat = Element::ellipse({0, 0}, 1, 1e-6, 0, 0, 2 * kPi);
  EXPECT_NEAR(flat.length(), 4.0, 1e-5);
  // A quarter of a circle written as an ellipse.
  const Element circle = Element::ellipse({0, 0}, 3, 3, 0, 0, -kPi / 2);
  EXPECT_NEAR(circle.length(), 1.5 * kPi, 1e-12);
  // Halves add up.
  EXPECT_NEAR(e.length_between(0, 0.5) + e.length_between(0.5, 1), e.length(), 1e-12);
}

TEST(Element, EllipseLengthOfManyTurnsOrFarAnglesEnds) {
  // Found by fuzz_glyph_script: a sweep of 1e77 rad, or a start where adding a quarter turn no
  // longer changes the angle, looped for ever. Whole turns are multiples of the perimeter.
  constexpr double kPerimeter = 9.688448220547675;  // semi-axes 2 and 1
  EXPECT_NEAR(ellipse_arc_length(2, 1, 0.3, 0.3 + 1000 * 2 * kPi + kPi), 1000.5 * kPerimeter,
              1000.5 * kPerimeter * 1e-9);
  EXPECT_NEAR(ellipse_arc_length(2, 1, 2 * kPi * 7 + 0.25, 2 * kPi * 7 + 1.25), ellipse_arc_length(2, 1, 0.25, 1.25),
              1e-9);
  EXPECT_TRUE(std::isfinite(ellipse_arc_length(2, 1, 1e20, 1e20 + 1)));
  EXPECT_TRUE(std::isfinite(ellipse_arc_length(2, 1, 0, 1e77)));
  EXPECT_TRUE(std::isnan(ellipse_arc_length(2, 1, 0, INFINITY)));
  // A radius whose square overflows: the length of the scaled ellipse, scaled back.
  EXPECT_NEAR(ellipse_arc_length(2.6, 2e169, 0.349, 4.71) / 2e169, ellipse_arc_length(2.6e-169, 1, 0.349, 4.71),
              1e-12);
}

TEST(Element, ArcBoundsIncludeAxisExtremes) {
  const Element a = Element::arc({0, 0}, 2, -kPi / 4, kPi / 2);  // through angle 0
  const Box b = a.bounds();
  EXPECT_NEAR(b.max.x(), 2.0, 1e-15);
  EXPECT_NEAR(b.min.x(), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(b.min.y(), -std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(b.max.y(), std::sqrt(2.0), 1e-12);
}

TEST(Element, EllipseBoundsMatchDenseSampling) {
  const Element e = Element::ellipse({1, -2}, 3, 1, 0.6, 0.2, 4.0);
  Box sampled;
  for (int i = 0; i <= 200000; ++i) sampled.add(e.point_at(i / 200000.0));
  const Box b = e.bounds();
  expect_near(b.min, sampled.min, 1e-9);
  expect_near(b.max, sampled.max, 1e-9);
}

TEST(Element, ReversedRunsBackwards) {
  for (const Element& e : {Element::line({0, 0}, {1, 2}), Element::arc({1, 1}, 2, 0.3, -1.2),
                           Element::ellipse({0, 0}, 2, 1, 0.4, 0.5, 2.0)}) {
    const Element r = e.reversed();
    for (double t : {0.0, 0.25, 0.7, 1.0}) {
      expect_near(r.point_at(t), e.point_at(1 - t), 1e-12);
      expect_near(r.tangent_at(t), -e.tangent_at(1 - t), 1e-12);
    }
    EXPECT_NEAR(r.length(), e.length(), 1e-12);
  }
}

// Sampled points of a transformed element equal the transformed sampled points.
void expect_exact_transform(const Element& e, const Affine& t) {
  const Element te = e.transformed(t);
  for (int i = 0; i <= 64; ++i) {
    const double u = i / 64.0;
    expect_near(te.point_at(u), t * e.point_at(u), 1e-9);
  }
}

TEST(Element, ShearTurnsCircularArcIntoExactEllipseArc) {
  const Element arc = Element::arc({2, 1}, 1.5, 0.4, 2.5);
  const Affine shear = make_affine(1, std::tan(15 * kPi / 180), 0, 1, 3, -1);
  const Element e = arc.transformed(shear);
  EXPECT_EQ(e.kind(), ElementKind::ellipse);
  expect_exact_transform(arc, shear);
}

TEST(Element, NonUniformScaleTurnsCircularArcIntoExactEllipseArc) {
  const Element arc = Element::arc({-1, 0.5}, 0.92, -2.0, -3.5);
  const Affine scale = make_affine(0.7, 0, 0, 1.3, 0, 0);
  EXPECT_EQ(arc.transformed(scale).kind(), ElementKind::ellipse);
  expect_exact_transform(arc, scale);
  // Scale plus shear plus rotation plus mirror, all at once.
  const Affine mixed = make_affine(-0.8, 0.35, 0.2, 1.1, 5, 7);
  expect_exact_transform(arc, mixed);
}

TEST(Element, SimilaritiesKeepCircularArcsCircular) {
  const Element arc = Element::arc({1, 2}, 2, 0.1, 1.9);
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Affine rotate = make_affine(2 * c, -2 * s, 2 * s, 2 * c, 1, -3);
  const Affine mirror = make_affine(-1, 0, 0, 1, 4, 0);
  const Affine reflect_rotated = make_affine(c, s, s, -c, 0, 0);
  for (const Affine& t : {rotate, mirror, reflect_rotated}) {
    const Element r = arc.transformed(t);
    EXPECT_EQ(r.kind(), ElementKind::arc);
    expect_exact_transform(arc, t);
  }
}

TEST(Element, EllipseArcsTransformExactly) {
  const Element e = Element::ellipse({0.5, -1}, 2, 0.7, 0.9, -0.3, 4.1);
  expect_exact_transform(e, make_affine(1, 0.4, 0, 1, 2, 2));          // shear
  expect_exact_transform(e, make_affine(-1, 0, 0, 1, 0, 0));           // mirror
  expect_exact_transform(e, make_affine(0.3, -0.95, 0.95, 0.3, 1, 1));  // rotation
  expect_exact_transform(e, make_affine(1.7, 0.2, -0.6, 0.4, 0, 0));   // general
}

TEST(Element, EllipseMadeRoundBecomesACircularArc) {
  // An x-stretched circle squeezed back is a circle again.
  const Element e = Element::ellipse({0, 0}, 2, 1, 0, 0.2, 1.0);
  const Element round = e.transformed(make_affine(0.5, 0, 0, 1, 0, 0));
  EXPECT_EQ(round.kind(), ElementKind::arc);
  EXPECT_NEAR(std::get<CircularArc>(round.geometry()).radius, 1.0, 1e-12);
  expect_exact_transform(e, make_affine(0.5, 0, 0, 1, 0, 0));
}

TEST(Element, TransformKeepsLaserFlag) {
  const Element off = Element::arc({0, 0}, 1, 0, 1, false);
  EXPECT_FALSE(off.transformed(make_affine(1, 0.3, 0, 1, 0, 0)).laser());
  EXPECT_FALSE(off.reversed().laser());
}

}  // namespace
}  // namespace mark
