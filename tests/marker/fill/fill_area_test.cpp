// Hatch area and containment on real TrueType letters (DejaVu Sans, Liberation Sans): the lines
// cover the letter's area minus the inset band to within 1 %, and no line leaves that area.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "marker/fill/fill_region.hpp"
#include "marker/fill/hatch_lines.hpp"
#include "marker/fill/hatch_order.hpp"
#include "marker/geometry/clipper_paths.hpp"
#include "tests/marker/fill/fill_test_support.hpp"

namespace mark {
namespace {

struct Case {
  std::string font;
  double angle_deg;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.font << " at " << c.angle_deg << " deg"; }

std::string name_of(const testing::TestParamInfo<Case>& info) {
  const std::string stem = info.param.font.find("DejaVu") != std::string::npos ? "DejaVuSans" : "LiberationSans";
  return stem + "_" + std::to_string(static_cast<int>(info.param.angle_deg)) + "deg";
}

class HatchArea : public testing::TestWithParam<Case> {};

constexpr const char* kLetters = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789&@%";
// Lines parallel to a straight stem cut it at an arbitrary phase, off by up to half a spacing on
// each side: the spacing is 1/100 of the thinnest stems (1 mm at this height), so that
// quantisation stays well inside 1 %.
constexpr double kHeight = 10, kSpacing = 0.01, kInset = 0.025;

TEST_P(HatchArea, LinesCoverTheInsetAreaWithinOnePercentAndStayInside) {
  double worst = 0;
  std::string worst_letter;
  for (const char* c = kLetters; *c; ++c) {
    const std::string letter(1, *c);
    const FillRegion region =
        make_fill_region(test::letter_contours(GetParam().font, letter, kHeight), FillRule::non_zero, 0.0005);
    const ClipperLib::Paths inset = region.inset(kInset);
    const double target = area_mm2(inset);
    ASSERT_GT(target, 1.0) << letter;
    const HatchFrame frame{{0.013, 0.007}, GetParam().angle_deg * std::numbers::pi / 180, kSpacing};
    Point at(0, 0);
    const std::vector<HatchLine> lines =
        order_hatch(hatch_pieces(inset, frame, 0.0), frame, HatchDirection::bidirectional,
                    HatchOrder::short_jumps, at);
    // The area grown by 10 nm: Clipper's integer grid may put a line's end that far outside.
    const ClipperLib::Paths grown = offset_region(inset, 1e-5, 1e-5);
    double length = 0;
    for (const HatchLine& l : lines) {
      length += (l.end - l.start).norm();
      // Both ends on the area's boundary (within Clipper's nanometre grid), the line inside.
      ASSERT_TRUE(contains(grown, l.start) && contains(grown, l.end)) << letter;
      ASSERT_TRUE(segment_inside(grown, l.start, l.end)) << letter;
    }
    const double error = std::abs(length * kSpacing - target) / target;
    if (error > worst) worst = error, worst_letter = letter;
    EXPECT_LT(error, 0.01) << "letter " << letter << ": hatch " << length * kSpacing << " mm², area "
                           << target << " mm²";
  }
  RecordProperty("worst_area_error_pct", std::to_string(100 * worst));
  std::printf("worst area error %.3f %% (letter %s)\n", 100 * worst, worst_letter.c_str());
}

INSTANTIATE_TEST_SUITE_P(Fonts, HatchArea,
                         testing::Values(Case{test::kDejaVuSans, 0}, Case{test::kDejaVuSans, 37},
                                         Case{test::kLiberationSans, 0}, Case{test::kLiberationSans, 90}),
                         name_of);

}  // namespace
}  // namespace mark
