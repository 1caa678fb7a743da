// The built-in marking font: coverage, metrics, true curves, stroke structure, no retraced strokes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "fonts/catalog.hpp"
#include "fonts/error.hpp"
#include "fonts/overloaded.hpp"

namespace mark {
namespace {

constexpr double kTol = 1e-9;

std::string name_of(char32_t cp) { return describe_code_point(cp); }

const Glyph& glyph(char c) { return builtin_font().glyph(static_cast<unsigned char>(c)); }

int count_kind(const Glyph& g, ElementKind kind) {
  return static_cast<int>(std::count_if(g.elements.begin(), g.elements.end(), [&](const Element& e) {
    return e.laser() && e.kind() == kind;
  }));
}

// Distance from p to the element, exact for lines and circular arcs; for elliptical arcs the
// closest of 64 samples refined by ternary search on the parameter (the distance is unimodal
// near its minimum), good to far below the 1e-6 the retrace test asks for.
double distance(const Element& e, const Point& p) {
  return std::visit(
      Overloaded{
          [&](const Line& l) {
            const Point d = l.end - l.start;
            const double t = std::clamp((p - l.start).dot(d) / d.squaredNorm(), 0.0, 1.0);
            return (l.start + t * d - p).norm();
          },
          [&](const CircularArc& a) {
            const double angle = std::atan2(p.y() - a.center.y(), p.x() - a.center.x());
            const double from = a.sweep >= 0 ? a.start_angle : a.start_angle + a.sweep;
            double d = std::fmod(angle - from, 2 * std::numbers::pi);
            if (d < 0) d += 2 * std::numbers::pi;
            if (d <= std::abs(a.sweep)) return std::abs((p - a.center).norm() - a.radius);
            return std::min((e.start() - p).norm(), (e.end() - p).norm());
          },
          [&](const EllipticalArc&) {
            constexpr int n = 64;
            int best = 0;
            for (int i = 1; i <= n; ++i)
              if ((e.point_at(double(i) / n) - p).norm() < (e.point_at(double(best) / n) - p).norm())
                best = i;
            double lo = std::max(0.0, (best - 1.0) / n), hi = std::min(1.0, (best + 1.0) / n);
            for (int k = 0; k < 60; ++k) {
              const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
              if ((e.point_at(m1) - p).norm() < (e.point_at(m2) - p).norm()) hi = m2;
              else lo = m1;
            }
            return (e.point_at((lo + hi) / 2) - p).norm();
          }},
      e.geometry());
}

// Longest stretch of `a` (in length units) that lies within 1e-6 of `b`: a retraced stroke shows
// up as a stretch longer than a touching or crossing point can make.
double overlap_length(const Element& a, const Element& b) {
  const double step = 0.02;
  const int n = std::max(2, static_cast<int>(std::ceil(a.length() / step)));
  Box near_b = b.bounds();
  near_b.add(near_b.min - Point(1e-3, 1e-3));
  near_b.add(near_b.max + Point(1e-3, 1e-3));
  double longest = 0, run = 0;
  bool inside_prev = false;
  for (int i = 0; i <= n; ++i) {
    const Point p = a.point_at(double(i) / n);
    Box at_p;
    at_p.add(p);
    const bool inside = near_b.contains(at_p) && distance(b, p) < 1e-6;
    run = inside && inside_prev ? run + a.length() / n : 0;
    longest = std::max(longest, run);
    inside_prev = inside;
  }
  return longest;
}

double longest_retrace(const Glyph& g) {
  double worst = 0;
  for (std::size_t i = 0; i < g.elements.size(); ++i)
    for (std::size_t j = 0; j < g.elements.size(); ++j) {
      const Element &a = g.elements[i], &b = g.elements[j];
      if (i == j || !a.laser() || !b.laser()) continue;
      worst = std::max(worst, overlap_length(a, b));
    }
  return worst;
}

// A curve faked with a polyline: three or more short lines in one stroke, each turning the same
// way by a small angle.
bool has_polyline_curve(const Glyph& g) {
  int run = 0;  // consecutive short lines in one stroke turning gently the same way
  double last_turn = 0;
  for (std::size_t i = 0; i < g.elements.size(); ++i) {
    const Element& e = g.elements[i];
    const bool short_line = e.laser() && e.kind() == ElementKind::line && e.length() < 2.0;
    if (!short_line) {
      run = 0;
      continue;
    }
    if (run > 0) {
      const Element& prev = g.elements[i - 1];
      const Point a = prev.tangent_at(1), b = e.tangent_at(0);
      const double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      const bool gentle = std::abs(turn) > 1e-9 && std::abs(turn) < 0.7;  // under 40°
      run = gentle && (run == 1 || turn * last_turn > 0) ? run + 1 : 1;
      last_turn = turn;
    } else {
      run = 1;
    }
    if (run >= 3) return true;
  }
  return false;
}

TEST(BuiltinFont, CoversPrintableAscii) {
  const StrokeFont& font = builtin_font();
  EXPECT_EQ(font.name(), "builtin");
  EXPECT_EQ(font.source(), "built-in");
  EXPECT_EQ(font.size(), 95u);
  for (char32_t cp = 0x20; cp <= 0x7E; ++cp) EXPECT_NE(font.find(cp), nullptr) << name_of(cp);
}

TEST(BuiltinFont, IsParsedOnceAndOpenedByName) {
  EXPECT_EQ(&builtin_font(), &builtin_font());
  EXPECT_EQ(open_font("builtin").get(), &builtin_font());
}

TEST(BuiltinFont, ReplacesMissingCharactersWithQuestionMark) {
  const StrokeFont& font = builtin_font();
  EXPECT_EQ(font.glyph_or_replacement(U'\u20AC').code_point, U'?');
  EXPECT_THROW(font.glyph(U'\u20AC'), MissingGlyphError);
}

TEST(BuiltinFont, MetricsFollowTheDesignGrid) {
  const FontMetrics& m = builtin_font().metrics();
  EXPECT_EQ(m.cap_height, 10);
  EXPECT_EQ(m.x_height, 7);
  EXPECT_EQ(m.ascender, 10);
  EXPECT_EQ(m.descender, -3);
  EXPECT_EQ(m.baseline, 0);
  EXPECT_EQ(m.standard_height, m.cap_height);
  EXPECT_EQ(m.line_height, 16);
  EXPECT_GT(m.word_spacing, 0);
  EXPECT_EQ(glyph(' ').advance, m.word_spacing);
  EXPECT_TRUE(glyph(' ').elements.empty());
  // Ascender and descender are the real extremes of the font.
  Box all;
  for (const auto& [cp, g] : builtin_font().glyphs()) all.add(g.bounds());
  EXPECT_NEAR(all.max.y(), m.ascender, kTol);
  EXPECT_NEAR(all.min.y(), m.descender, kTol);
}

// No overshoot in this design: round capitals and digits touch the cap line and the baseline
// exactly, like the flat ones (as in ISO 3098 lettering).
TEST(BuiltinFont, CapitalsAndDigitsStandOnTheBaselineAndReachCapHeight) {
  const std::string chars = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  for (char c : chars) {
    const Box b = glyph(c).bounds();
    EXPECT_NEAR(b.max.y(), 10, kTol) << c;
    EXPECT_NEAR(b.min.y(), 0, kTol) << c;
  }
}

TEST(BuiltinFont, LowerCaseKeepsXHeightAscendersAndDescenders) {
  for (char c : std::string("acemnorsuvwxz")) {
    const Box b = glyph(c).bounds();
    EXPECT_NEAR(b.max.y(), 7, kTol) << c;
    EXPECT_NEAR(b.min.y(), 0, kTol) << c;
  }
  for (char c : std::string("bdfhkl")) {
    const Box b = glyph(c).bounds();
    EXPECT_NEAR(b.max.y(), 10, kTol) << c;
    EXPECT_NEAR(b.min.y(), 0, kTol) << c;
  }
  for (char c : std::string("gpqy")) {
    const Box b = glyph(c).bounds();
    EXPECT_NEAR(b.max.y(), 7, kTol) << c;
    EXPECT_NEAR(b.min.y(), -3, kTol) << c;
  }
  EXPECT_NEAR(glyph('j').bounds().min.y(), -3, kTol);
  // The dots of i and j sit between the x-height and the ascender; t is shorter than l.
  for (char c : std::string("ij")) {
    EXPECT_GT(glyph(c).bounds().max.y(), 9) << c;
    EXPECT_LT(glyph(c).bounds().max.y(), 10) << c;
  }
  EXPECT_NEAR(glyph('t').bounds().max.y(), 9, kTol);
}

TEST(BuiltinFont, DigitsShareOneAdvanceSoSerialNumbersLineUp) {
  for (char c = '0'; c <= '9'; ++c) EXPECT_EQ(glyph(c).advance, 8) << c;
}

TEST(BuiltinFont, RoundShapesAreTrueArcs) {
  const std::string curved = "OQCGSDUJBPR0235689abcdeghjmnopqrsu@&()?${}~%";
  for (char c : curved) {
    const Glyph& g = glyph(c);
    EXPECT_GT(count_kind(g, ElementKind::arc) + count_kind(g, ElementKind::ellipse), 0) << c;
  }
  // Wholly round shapes have no straight piece at all.
  for (char c : std::string("OC0o()cS8s")) {
    EXPECT_EQ(count_kind(glyph(c), ElementKind::line), 0) << c;
    EXPECT_GT(count_kind(glyph(c), ElementKind::ellipse) + count_kind(glyph(c), ElementKind::arc), 0) << c;
  }
  // O and 0 are one full ellipse each, and the narrower 0 stays distinguishable from O.
  for (char c : std::string("O0o")) {
    ASSERT_EQ(glyph(c).elements.size(), 1u) << c;
    const auto& e = std::get<EllipticalArc>(glyph(c).elements[0].geometry());
    EXPECT_NEAR(std::abs(e.sweep), 2 * std::numbers::pi, kTol) << c;
  }
  EXPECT_LT(glyph('0').bounds().width() + 0.9, glyph('O').bounds().width());
}

TEST(BuiltinFont, NoCurveIsFakedWithAPolyline) {
  for (const auto& [cp, g] : builtin_font().glyphs()) EXPECT_FALSE(has_polyline_curve(g)) << name_of(cp);
}

TEST(BuiltinFont, NoStrokeIsRetraced) {
  for (const auto& [cp, g] : builtin_font().glyphs())
    EXPECT_LT(longest_retrace(g), 0.05) << name_of(cp);
}

TEST(BuiltinFont, GlyphsAreOneContinuousPathOfStrokesAndShortMoves) {
  for (const auto& [cp, g] : builtin_font().glyphs()) {
    EXPECT_GT(g.advance, 0) << name_of(cp);
    if (cp == U' ') continue;
    ASSERT_FALSE(g.elements.empty()) << name_of(cp);
    EXPECT_TRUE(g.elements.front().laser()) << name_of(cp) << " starts with a move";
    EXPECT_TRUE(g.elements.back().laser()) << name_of(cp) << " ends with a move";
    double moved = 0;
    for (std::size_t i = 0; i < g.elements.size(); ++i) {
      const Element& e = g.elements[i];
      if (i > 0) {
        EXPECT_LT((e.start() - g.elements[i - 1].end()).norm(), kTol) << name_of(cp) << " element " << i;
      }
      if (e.laser()) continue;
      EXPECT_EQ(e.kind(), ElementKind::line) << name_of(cp);
      ASSERT_TRUE(i > 0 && i + 1 < g.elements.size()) << name_of(cp);
      EXPECT_TRUE(g.elements[i - 1].laser() && g.elements[i + 1].laser()) << name_of(cp);
      // A short move would be a gap in what should be one stroke.
      EXPECT_GT(e.length(), 0.5) << name_of(cp) << " element " << i;
      moved += e.length();
    }
    // Strokes are ordered so that no glyph travels more than its own height with the laser off.
    EXPECT_LE(moved, 10 + kTol) << name_of(cp);
  }
}

TEST(BuiltinFont, GlyphsStayInsideTheirAdvance) {
  for (const auto& [cp, g] : builtin_font().glyphs()) {
    if (cp == U' ') continue;
    const Box b = g.bounds();
    EXPECT_GE(b.min.x(), 0 - kTol) << name_of(cp);
    EXPECT_LE(b.max.x(), g.advance + kTol) << name_of(cp);
    if (cp == U'_') continue;  // underscores join up into one rule
    EXPECT_GE(b.min.x(), 0.25) << name_of(cp);
    EXPECT_GE(g.advance - b.max.x(), 0.25) << name_of(cp);
  }
}

// The checks above would be worthless if they could not fail.
TEST(BuiltinFontChecks, DetectRetracesAndFakeCurves) {
  Glyph retraced;
  retraced.elements = {Element::line({0, 0}, {4, 0}), Element::line({4, 0}, {2, 0})};
  EXPECT_NEAR(longest_retrace(retraced), 2.0, 0.02);
  Glyph arc_over_arc;
  arc_over_arc.elements = {Element::arc({0, 0}, 3, 0, 1.0), Element::arc({0, 0}, 3, 0.5, 1.0)};
  EXPECT_GT(longest_retrace(arc_over_arc), 1.4);
  Glyph ellipse_over_ellipse;
  ellipse_over_ellipse.elements = {Element::ellipse({0, 0}, 3, 5, 0, 0, 1.0),
                                   Element::ellipse({0, 0}, 3, 5, 0, 0.9, -0.5)};
  EXPECT_GT(longest_retrace(ellipse_over_ellipse), 1.0);
  Glyph touching;  // a bowl tangent to a stem, a crossing: points, not lengths
  touching.elements = {Element::line({1, 0}, {1, 7}), Element::arc({4, 4}, 3, std::numbers::pi, -std::numbers::pi),
                       Element::line({0, 0}, {7, 7})};
  EXPECT_LT(longest_retrace(touching), 0.05);


  Glyph polygon;  // a quarter circle as six chords
  for (int k = 0; k < 6; ++k) {
    const double a0 = k * std::numbers::pi / 12, a1 = (k + 1) * std::numbers::pi / 12;
    polygon.elements.push_back(Element::line({3 * std::cos(a0), 3 * std::sin(a0)}, {3 * std::cos(a1), 3 * std::sin(a1)}));
  }
  EXPECT_TRUE(has_polyline_curve(polygon));
  EXPECT_FALSE(has_polyline_curve(glyph('M')));
}

}  // namespace
}  // namespace mark
