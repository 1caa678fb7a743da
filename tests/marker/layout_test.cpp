// Text layout against the CNC paper: its letter "D" (Table 2), linear / inclined / circular
// fitting with the paper's formulas, font inclination, mirroring, and refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/numbers.hpp"
#include "fonts/error.hpp"
#include "fonts/stroke_font.hpp"
#include "marker/layout/layout.hpp"

namespace mark {
namespace {

// The paper's Table 2, standard text height 3: start, end and radius of each entity.
StrokeFont paper_font() {
  FontMetrics m;
  m.cap_height = m.standard_height = 3;
  m.line_height = 5;
  m.word_spacing = 2;
  StrokeFont font("paper", "Kannan et al. Table 2", m);
  Glyph d;
  d.code_point = U'D';
  d.elements = {Element::line({0, 0}, {0.749, 0}),
                Element::arc_through({0.749, 0}, {1.6646, 0.9167}, 0.92, true),
                Element::line({1.6646, 0.9167}, {1.6646, 2.0835}),
                Element::arc_through({1.6646, 2.0835}, {0.8020, 2.9807}, 0.92, true),
                Element::line({0.8020, 2.9807}, {0, 3}),
                Element::line({0, 3}, {0, 0})};
  d.advance = 1.6646;  // W: the paper steps letters by W + G
  font.add(d);
  Glyph l;  // a plain "L" to have a second, asymmetric letter
  l.code_point = U'L';
  l.elements = {Element::line({0, 3}, {0, 0}), Element::line({0, 0}, {1.5, 0})};
  l.advance = 1.5;
  font.add(l);
  return font;
}

void expect_near(const Point& a, const Point& b, double tol) {
  EXPECT_NEAR(a.x(), b.x(), tol);
  EXPECT_NEAR(a.y(), b.y(), tol);
}

TEST(Layout, PaperLetterDReproducesTable2) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  o.height_mm = 3;
  const Figure f = layout_text("D", font, o);
  ASSERT_EQ(f.glyphs.size(), 1u);
  const auto& e = f.glyphs[0].elements;
  ASSERT_EQ(e.size(), 6u);
  const Point table[6][2] = {{{0, 0}, {0.749, 0}},           {{0.749, 0}, {1.6646, 0.9167}},
                             {{1.6646, 0.9167}, {1.6646, 2.0835}}, {{1.6646, 2.0835}, {0.8020, 2.9807}},
                             {{0.8020, 2.9807}, {0, 3}},      {{0, 3}, {0, 0}}};
  for (int i = 0; i < 6; ++i) {
    expect_near(e[i].start(), table[i][0], 1e-9);
    expect_near(e[i].end(), table[i][1], 1e-9);
  }
  for (int i : {1, 3}) {
    ASSERT_EQ(e[i].kind(), ElementKind::arc);
    const auto& arc = std::get<CircularArc>(e[i].geometry());
    EXPECT_NEAR(arc.radius, 0.92, 1e-3);
    EXPECT_NEAR((e[i].start() - arc.center).norm(), 0.92, 1e-3);
    EXPECT_NEAR((e[i].end() - arc.center).norm(), 0.92, 1e-3);
  }
}

TEST(Layout, ScalingAndLinearFittingStepByWPlusG) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  o.height_mm = 6;  // twice the standard height
  o.gap_mm = 0.5;
  o.base = Point(10, -4);
  const Figure f = layout_text("DDD", font, o);
  ASSERT_EQ(f.glyphs.size(), 3u);
  const double w = 2 * 1.6646;
  for (int i = 0; i < 3; ++i) expect_near(f.glyphs[i].origin, {10 + i * (w + 0.5), -4}, 1e-12);
  // The D's arcs scale with it and stay circular.
  const auto& arc = std::get<CircularArc>(f.glyphs[2].elements[1].geometry());
  EXPECT_NEAR(arc.radius, 1.84, 2e-3);
  expect_near(f.glyphs[2].elements[4].end(), {10 + 2 * (w + 0.5), 2}, 1e-12);
}

TEST(Layout, AlignmentAndLines) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  o.height_mm = 3;
  o.align = Align::right;
  o.base = Point(5, 0);
  const Figure f = layout_text("DL\nL", font, o);
  ASSERT_EQ(f.glyphs.size(), 3u);
  expect_near(f.glyphs[0].origin, {5 - 1.6646 - 1.5, 0}, 1e-12);
  expect_near(f.glyphs[2].origin, {5 - 1.5, -5}, 1e-12);  // second line one line height down
  EXPECT_EQ(f.glyphs[2].line, 1u);
  o.align = Align::center;
  const Figure c = layout_text("DL", font, o);
  EXPECT_NEAR(c.glyphs[0].origin.x(), 5 - (1.6646 + 1.5) / 2, 1e-12);
}

TEST(Layout, InclinedFittingRotatesAboutTheBasePoint) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  o.height_mm = 3;
  o.base = Point(1, 2);
  o.angle_deg = 30;
  const Figure f = layout_text("LD", font, o);
  const double a = kPi / 6;
  expect_near(f.glyphs[1].origin, Point(1, 2) + 1.5 * Point(std::cos(a), std::sin(a)), 1e-12);
  EXPECT_NEAR(f.glyphs[1].rotation_rad, a, 1e-15);
  // L's foot runs along the inclined baseline.
  const Point foot = f.glyphs[0].elements[1].end() - f.glyphs[0].elements[1].start();
  EXPECT_NEAR(std::atan2(foot.y(), foot.x()), a, 1e-12);
}

// Circular fitting: letter i's baseline centre sits on the circle at
// θ_i − W_i/(2R), θ_i = θs − Σ_{j<i}(W_j + G)/R, and the letter is rotated by that angle − 90°.
TEST(Layout, CircularFittingFollowsThePaperFormulas) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  o.height_mm = 3;
  o.gap_mm = 0.4;
  o.circle = CircleFit{Point(3, -2), 12.0, 150.0, false};
  const std::string text = "DLDDL";
  const Figure f = layout_text(text, font, o);
  ASSERT_EQ(f.glyphs.size(), text.size());
  double theta = 150.0 * kPi / 180;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const double w = text[i] == 'D' ? 1.6646 : 1.5;
    const double centre_angle = theta - w / (2 * 12.0);
    EXPECT_NEAR(f.glyphs[i].rotation_rad, centre_angle - kPi / 2, 1e-9) << i;
    const Point baseline_centre = f.glyphs[i].placement() * Point(w / 2, 0);
    EXPECT_NEAR((baseline_centre - Point(3, -2)).norm(), 12.0, 1e-9) << i;
    const Point radial = baseline_centre - Point(3, -2);
    EXPECT_NEAR(std::atan2(radial.y(), radial.x()), centre_angle, 1e-9) << i;
    theta -= (w + 0.4) / 12.0;  // Δθ = (W + G)/R
  }
}

TEST(Layout, SelfCentredTextIsSymmetricAboutNinetyDegrees) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  o.height_mm = 3;
  o.gap_mm = 0.3;
  o.circle = CircleFit{Point(0, 0), 10.0, std::nullopt, false};
  const Figure f = layout_text("DDDD", font, o);
  // θs = 90° + θt/2 with θt = S_T/R, S_T = nW + (n − 1)G.
  const double st = 4 * 1.6646 + 3 * 0.3;
  const double theta_s = kPi / 2 + st / 10.0 / 2;
  EXPECT_NEAR(f.glyphs[0].rotation_rad, theta_s - 1.6646 / 20.0 - kPi / 2, 1e-9);
  // Mirror pairs about the y axis: rotations opposite, origins' bounds mirror.
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(f.glyphs[i].rotation_rad, -f.glyphs[3 - i].rotation_rad, 1e-9);
    const Point ci = f.glyphs[i].placement() * Point(1.6646 / 2, 0);
    const Point cj = f.glyphs[3 - i].placement() * Point(1.6646 / 2, 0);
    EXPECT_NEAR(ci.x(), -cj.x(), 1e-9);
    EXPECT_NEAR(ci.y(), cj.y(), 1e-9);
  }
}

TEST(Layout, InsideTextReadsAlongTheBottom) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  o.height_mm = 3;
  o.circle = CircleFit{Point(0, 0), 10.0, std::nullopt, true};
  const Figure f = layout_text("LL", font, o);
  // Centred on 270°, letters upright at the bottom, tops toward the centre, reading left to right.
  EXPECT_LT(f.glyphs[0].origin.x(), f.glyphs[1].origin.x());
  const Point c0 = f.glyphs[0].placement() * Point(0.75, 0);
  const Point c1 = f.glyphs[1].placement() * Point(0.75, 0);
  EXPECT_NEAR(c0.norm(), 10.0, 1e-9);
  EXPECT_NEAR(c0.x(), -c1.x(), 1e-9);
  EXPECT_NEAR(c0.y(), c1.y(), 1e-9);
  EXPECT_LT(c0.y(), -9.0);
  // The letter's top (y = 3 in its frame) lies closer to the centre than its baseline.
  const Point top = f.glyphs[0].placement() * Point(0.75, 3);
  EXPECT_NEAR(top.norm(), 7.0, 1e-9);
}

TEST(Layout, ItalicShearGivesExactEllipseArcs) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  o.height_mm = 3;
  o.italic_deg = 12;
  const Figure f = layout_text("D", font, o);
  const auto& e = f.glyphs[0].elements;
  ASSERT_EQ(e[1].kind(), ElementKind::ellipse);
  const double k = std::tan(12 * kPi / 180);
  const StrokeFont reference = paper_font();
  const Element original = reference.glyph(U'D').elements[1];
  for (int i = 0; i <= 32; ++i) {
    const Point p = original.point_at(i / 32.0);
    expect_near(e[1].point_at(i / 32.0), Point(p.x() + k * p.y(), p.y()), 1e-9);
  }
  // Width factor makes ellipses too.
  o.italic_deg = 0;
  o.width_factor = 0.8;
  const Figure w = layout_text("D", font, o);
  ASSERT_EQ(w.glyphs[0].elements[3].kind(), ElementKind::ellipse);
  const Element upper = reference.glyph(U'D').elements[3];
  const Point p = upper.point_at(0.37);
  expect_near(w.glyphs[0].elements[3].point_at(0.37), Point(0.8 * p.x(), p.y()), 1e-9);
}

TEST(Layout, MirrorIsTheMirrorImageOfTheLine) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  o.height_mm = 3;
  o.gap_mm = 0.25;
  o.italic_deg = 10;
  const Figure plain = layout_text("LDL", font, o);
  o.mirror = true;
  const Figure mirrored = layout_text("LDL", font, o);
  const double width = plain.glyphs.back().origin.x() + 1.5;
  // Reverse order: the mirrored line's glyph i is the plain glyph n−1−i reflected about x = W/2.
  ASSERT_EQ(mirrored.glyphs.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& m = mirrored.glyphs[i].elements;
    const auto& p = plain.glyphs[2 - i].elements;
    ASSERT_EQ(m.size(), p.size());
    for (std::size_t j = 0; j < m.size(); ++j)
      for (double t : {0.0, 0.3, 1.0}) {
        const Point q = p[j].point_at(t);
        expect_near(m[j].point_at(t), Point(width - q.x(), q.y()), 1e-9);
      }
  }
  EXPECT_EQ(mirrored.glyphs[0].code_point, U'L');
  EXPECT_EQ(mirrored.glyphs[1].code_point, U'D');
}

TEST(Layout, DistinctCharactersAreShapedOnce) {
  const StrokeFont font = paper_font();
  const Figure f = layout_text("DLDLDD", font, LayoutOptions{});
  EXPECT_EQ(f.shapes.size(), 2u);
  EXPECT_EQ(f.glyphs.size(), 6u);
}

TEST(Layout, RefusesBadInput) {
  const StrokeFont font = paper_font();
  LayoutOptions o;
  try {
    layout_text("DX", font, o);
    FAIL() << "missing glyph accepted";
  } catch (const MissingGlyphError& e) {
    EXPECT_STREQ(e.what(), "font 'paper' has no glyph for 'X' (U+0058)");
  }
  o.height_mm = 0;
  EXPECT_THROW(layout_text("D", font, o), InputError);
  o.height_mm = 3;
  o.width_factor = std::nan("");
  EXPECT_THROW(layout_text("D", font, o), InputError);
  o.width_factor = 1;
  o.circle = CircleFit{Point(0, 0), 0.1, std::nullopt, false};
  EXPECT_THROW(layout_text("DDDD", font, o), InputError);  // longer than the circumference
  o.circle.reset();
  EXPECT_THROW(layout_text("D\xff", font, o), InputError);  // invalid UTF-8
}

TEST(Layout, ReplacementGlyphOnRequest) {
  StrokeFont font = paper_font();
  font.set_replacement(U'L');
  LayoutOptions o;
  o.replace_missing = true;
  const Figure f = layout_text("DX", font, o);
  ASSERT_EQ(f.glyphs.size(), 2u);
  EXPECT_EQ(f.glyphs[1].elements.size(), 2u);  // drawn as the L
}

TEST(Layout, FieldCheckNamesTheOverflow) {
  Box b;
  b.add(Point(-10, 0));
  b.add(Point(60, 5));
  try {
    require_inside(b, Field{110}, "the text layout");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x -10.000 to 60.000 mm"), std::string::npos) << e.what();
  }
  Box inside;
  inside.add(Point(-55, -55));
  inside.add(Point(55, 55));
  EXPECT_NO_THROW(require_inside(inside, Field{110}, "x"));
}

}  // namespace
}  // namespace mark
