// Overlapping contours are unioned before hatching: on the simulated scanner the overlap gets the
// same dose as the rest (no double-burned strip), where hatching each contour on its own doubles
// it. The fill rules differ where they should: nested loops of the same orientation are one area
// under non-zero and a ring under even-odd.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "driver/sim/sim_scanner.hpp"
#include "marker/fill/fill.hpp"
#include "marker/fill/fill_region.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/simulate_plan.hpp"
#include "marker/plan/plan.hpp"
#include "tests/marker/fill/fill_test_support.hpp"

namespace mark {
namespace {

using test::box;

// Mean dose per mm² over a window of the raster.
double mean_dose(const DoseRaster& dose, const Box& w) {
  const double px = dose.pixel_mm();
  double sum = 0;
  std::size_t n = 0;
  for (auto iy = static_cast<std::int64_t>(std::ceil(w.min.y() / px)); iy * px <= w.max.y(); ++iy)
    for (auto ix = static_cast<std::int64_t>(std::ceil(w.min.x() / px)); ix * px <= w.max.x(); ++ix) {
      sum += dose.pixel(ix, iy);
      ++n;
    }
  return sum / (static_cast<double>(n) * px * px);
}

Figure one_glyph(std::vector<Element> elements) {
  Figure f;
  PlacedGlyph g;
  g.code_point = U'#';
  g.elements = std::move(elements);
  f.glyphs.push_back(std::move(g));
  return f;
}

// Marks the figure on the simulated SL10 with the default blanking pen at 1000 mm/s.
std::unique_ptr<SimScanner> mark_on_sl10(const Figure& f) {
  const Pen pen = pen_for_head(head_sl10(), CornerStrategy::blanking, 1000);
  const Plan plan = plan_figure(f, pen);
  auto sim = std::make_unique<SimScanner>(simulator_options(head_sl10(), pen));
  simulate_plan(plan, *sim);
  return sim;
}

TEST(FillUnion, OverlapOfTwoSquaresGetsTheSameDoseAsTheRest) {
  const Contour a = rectangle_contour(box(0, 0, 2, 2));
  const Contour b = rectangle_contour(box(1, 0, 3, 2));
  FillOptions o;
  o.sets = {{90, 0.05}};  // lines across the seams between overlap and the rest
  Point at(0, 0);
  const Filled unioned = fill_contours({a, b}, o, at);
  EXPECT_NEAR(unioned.stats.area_mm2, 6.0, 1e-9);
  // The same squares hatched one after the other, as a hatcher without the union would.
  std::vector<Element> separate = fill_contours({a}, o, at).elements;
  const Filled second = fill_contours({b}, o, at);
  separate.push_back(Element::line(separate.back().end(), second.elements.front().start(), false));
  separate.insert(separate.end(), second.elements.begin(), second.elements.end());

  const Box left = box(0.3, 0.4, 0.8, 1.6), overlap = box(1.2, 0.4, 1.8, 1.6), right = box(2.2, 0.4, 2.7, 1.6);
  const auto u = mark_on_sl10(one_glyph(unioned.elements));
  const double ratio_u = mean_dose(u->dose(), overlap) / mean_dose(u->dose(), left);
  EXPECT_NEAR(ratio_u, 1.0, 0.05);
  EXPECT_NEAR(mean_dose(u->dose(), right) / mean_dose(u->dose(), left), 1.0, 0.05);
  const auto s = mark_on_sl10(one_glyph(separate));
  const double ratio_s = mean_dose(s->dose(), overlap) / mean_dose(s->dose(), left);
  EXPECT_NEAR(ratio_s, 2.0, 0.1);
  std::printf("overlap/outside dose: unioned %.3f, hatched separately %.3f\n", ratio_u, ratio_s);
}

TEST(FillUnion, NonZeroFillsNestedLoopsEvenOddLeavesTheRing) {
  // Both loops counter-clockwise: winding 2 inside the inner one.
  const std::vector<Contour> nested = {rectangle_contour(box(0, 0, 4, 4)), rectangle_contour(box(1, 1, 3, 3))};
  EXPECT_NEAR(make_fill_region(nested, FillRule::non_zero, 0.0005).area_mm2(), 16.0, 1e-9);
  EXPECT_NEAR(make_fill_region(nested, FillRule::even_odd, 0.0005).area_mm2(), 12.0, 1e-9);
  FillOptions o;
  o.rule = FillRule::even_odd;
  o.inset_mm = 0;
  o.sets = {{0, 0.1}};
  Point at(0, 0);
  const Filled ring = fill_contours(nested, o, at);
  // 40 rows; the 20 rows through the hole are cut in two.
  EXPECT_EQ(ring.stats.hatch_lines, 60u);
  EXPECT_NEAR(ring.stats.hatch_length_mm * 0.1, 12.0, 1e-9);
  for (const Element& e : ring.elements) {
    if (!e.laser()) continue;
    const Point m = (e.start() + e.end()) / 2;
    EXPECT_FALSE(m.x() > 1 && m.x() < 3 && m.y() > 1 && m.y() < 3) << "a line through the hole";
  }
}

}  // namespace
}  // namespace mark
