// The next part of a series: relayout_text() and the Replanner give exactly what a fresh
// layout and plan give, while transforming and planning only the glyphs that changed.
#include <gtest/gtest.h>

#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/layout/layout.hpp"
#include "marker/plan/replan.hpp"
#include "tests/marker/param_print.hpp"

namespace mark {
namespace {

void expect_same_plan(const Plan& a, const Plan& b) {
  ASSERT_EQ(a.commands.size(), b.commands.size());
  for (std::size_t i = 0; i < a.commands.size(); ++i) {
    EXPECT_EQ(a.commands[i].kind, b.commands[i].kind) << i;
    EXPECT_LT((a.commands[i].end() - b.commands[i].end()).norm(), 1e-12) << i;
    EXPECT_DOUBLE_EQ(a.commands[i].speed_mm_s, b.commands[i].speed_mm_s) << i;
  }
  EXPECT_EQ(a.strokes, b.strokes);
  EXPECT_NEAR(a.jump_length_mm, b.jump_length_mm, 1e-9);
}

class Incremental : public testing::TestWithParam<CornerStrategy> {};

TEST_P(Incremental, SerialSeriesMatchesFreshLayoutAndPlan) {
  const auto font = open_font(kBuiltinFontName);
  LayoutOptions o;
  o.height_mm = 3;
  o.base = Point(-20, 0);
  const Pen pen = pen_for_head(head_sl10(), GetParam(), 1000);
  Figure figure;
  Replanner replanner(pen);
  const char* texts[] = {"SN 2026-A17-00004711", "SN 2026-A17-00004722", "SN 2026-A17-00004733",
                         "SN 2026-A17-00004733", "SN 2026-B17-00004733", "SN 2026-A17-000047"};
  const std::size_t expected_replanned[] = {20, 2, 2, 0, 12, 10};
  for (std::size_t i = 0; i < std::size(texts); ++i) {
    relayout_text(texts[i], *font, o, figure);
    const Figure fresh = layout_text(texts[i], *font, o);
    ASSERT_EQ(figure.glyphs.size(), fresh.glyphs.size());
    for (std::size_t g = 0; g < fresh.glyphs.size(); ++g) {
      ASSERT_EQ(figure.glyphs[g].elements.size(), fresh.glyphs[g].elements.size());
      for (std::size_t e = 0; e < fresh.glyphs[g].elements.size(); ++e)
        EXPECT_LT((figure.glyphs[g].elements[e].end() - fresh.glyphs[g].elements[e].end()).norm(), 1e-12);
    }
    const Plan& plan = replanner.update(figure);
    const Plan full = plan_figure(fresh, pen);
    expect_same_plan(plan, full);
    const Box fb = full.bounds();
    EXPECT_LT((replanner.bounds().min - fb.min).norm(), 1e-12);
    EXPECT_LT((replanner.bounds().max - fb.max).norm(), 1e-12);
    EXPECT_EQ(replanner.replanned_glyphs(), expected_replanned[i]) << texts[i];
  }
}

INSTANTIATE_TEST_SUITE_P(Corners, Incremental,
                         testing::Values(CornerStrategy::blanking, CornerStrategy::delays,
                                         CornerStrategy::none),
                         [](const testing::TestParamInfo<CornerStrategy>& info) {
                           return std::string(to_string(info.param));
                         });

TEST(Incremental, CentredTextThatChangesWidthIsReplacedWhole) {
  const auto font = open_font(kBuiltinFontName);
  LayoutOptions o;
  o.align = Align::center;
  Figure figure;
  relayout_text("SN 11", *font, o, figure);
  relayout_text("SN 1W", *font, o, figure);  // a wider last letter moves every glyph
  const Figure fresh = layout_text("SN 1W", *font, o);
  for (std::size_t g = 0; g < fresh.glyphs.size(); ++g)
    EXPECT_LT((figure.glyphs[g].origin - fresh.glyphs[g].origin).norm(), 1e-12);
}

}  // namespace
}  // namespace mark
