// Contour passes keep the outline's exact geometry: a loop at the outline itself, and loops
// inset from it, come back as lines and arcs (not chords) that lie at the inset distance from
// the exact outline, and each loop is closed end to start.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "marker/fill/contour_passes.hpp"
#include "marker/fill/fill.hpp"
#include "marker/geometry/flatten.hpp"
#include "tests/marker/fill/fill_test_support.hpp"

namespace mark {
namespace {

double segment_distance(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-30), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

// Distance from p to the exact outline (flattened at 0.05 µm, far below what is checked).
double outline_distance(const std::vector<Contour>& contours, const Point& p) {
  double best = INFINITY;
  for (const Contour& c : contours)
    for (const Element& e : c.elements) {
      if ((e.bounds().center() - p).norm() > best + e.bounds().width() + e.bounds().height()) continue;
      const std::vector<Point> pts = flatten_element(e, 5e-5);
      for (std::size_t k = 0; k + 1 < pts.size(); ++k) best = std::min(best, segment_distance(p, pts[k], pts[k + 1]));
    }
  return best;
}

struct LoopFigures {
  double max_error_um = 0;  // |distance to the outline − inset|, largest over points along the loops
  double arc_share = 0;     // share of the loops' length on circular arcs
  std::size_t elements = 0;
};

LoopFigures check_loops(const std::vector<Contour>& contours, double inset) {
  FillOptions o;
  o.sets.clear();
  o.contour_passes = 1;
  o.contour_inset_mm = inset;
  const FillRegion region = make_fill_region(contours, o.rule, o.chord_tolerance_mm);
  Point at(0, 0);
  const auto loops = contour_loops(region, o, at);
  EXPECT_FALSE(loops.empty());
  LoopFigures f;
  double arc_len = 0, len = 0;
  for (const auto& loop : loops) {
    EXPECT_LT((loop.back().end() - loop.front().start()).norm(), 1e-9) << "loop not closed";
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Element& e = loop[k];
      if (k > 0) {
        EXPECT_LT((e.start() - loop[k - 1].end()).norm(), 1e-9);
      }
      EXPECT_NE(e.kind(), ElementKind::ellipse);
      len += e.length();
      if (e.kind() == ElementKind::arc) arc_len += e.length();
      for (double t : {0.0, 0.25, 0.5, 0.75})
        f.max_error_um = std::max(f.max_error_um, 1e3 * std::abs(outline_distance(contours, e.point_at(t)) - inset));
    }
    f.elements += loop.size();
  }
  f.arc_share = arc_len / len;
  return f;
}

class ContourPass : public testing::TestWithParam<const char*> {};

TEST_P(ContourPass, LoopAtTheOutlineIsTheOutlineAsArcs) {
  const std::vector<Contour> c = test::letter_contours(test::kDejaVuSans, GetParam(), 10);
  std::size_t source_elements = 0;
  double arc_len = 0, len = 0;
  for (const Contour& k : c)
    for (const Element& e : k.elements) {
      ++source_elements;
      len += e.length();
      if (e.kind() == ElementKind::arc) arc_len += e.length();
    }
  const LoopFigures f = check_loops(c, 0.0);
  EXPECT_LT(f.max_error_um, 1.5);
  // Arcs are split at most into quarter turns: no more than twice the source's elements.
  EXPECT_LE(f.elements, 2 * source_elements);
  EXPECT_NEAR(f.arc_share, arc_len / len, 0.01);
  std::printf("%s at the outline: %zu elements (source %zu), %.0f %% arcs, off by ≤ %.2f µm\n",
              GetParam(), f.elements, source_elements, 100 * f.arc_share, f.max_error_um);
}

TEST_P(ContourPass, InsetLoopStaysAtTheInsetAsArcs) {
  const std::vector<Contour> c = test::letter_contours(test::kDejaVuSans, GetParam(), 10);
  const LoopFigures f = check_loops(c, 0.05);
  EXPECT_LT(f.max_error_um, 1.5);
  std::printf("%s inset 50 µm: %zu elements, %.0f %% arcs, off by ≤ %.2f µm\n", GetParam(),
              f.elements, 100 * f.arc_share, f.max_error_um);
}

INSTANTIATE_TEST_SUITE_P(DejaVuSans, ContourPass, testing::Values("O", "S", "B", "8", "g", "e"),
                         [](const auto& info) { return std::string(info.param); });

TEST(ContourPass, SquareStaysFourLinesAndCornersBecomeSharpInside) {
  const std::vector<Contour> c = {rectangle_contour(test::box(0, 0, 4, 2))};
  FillOptions o;
  o.sets.clear();
  o.contour_passes = 3;
  o.contour_inset_mm = 0.1;
  o.contour_spacing_mm = 0.2;
  const FillRegion region = make_fill_region(c, o.rule, o.chord_tolerance_mm);
  Point at(0, 0);
  const auto loops = contour_loops(region, o, at);
  ASSERT_EQ(loops.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    ASSERT_EQ(loops[k].size(), 4u);
    double len = 0;
    for (const Element& e : loops[k]) len += e.length();
    const double inset = 0.1 + 0.2 * static_cast<double>(k);
    EXPECT_NEAR(len, 2 * (4 - 2 * inset) + 2 * (2 - 2 * inset), 1e-5);
  }
}

}  // namespace
}  // namespace mark
