// The control point generator against the seed's own cases (US 6,007,230 FIG. 3, 4, 4A) and its
// rules: under 1 % the stylus stays above the surface, above 90 % entry and exit stay below it,
// the multiple-frequency split when d1 and d4 each exceed d2 + d3, the centre at the centre of
// image density, and the CT / LW scalers.
#include "marker/gravure/control_points.hpp"

#include <gtest/gtest.h>

namespace mark {
namespace {

constexpr double kTol = 1e-6;  // densities are floats

// CT: 40 µm full cell, 8 µm channel; LW: 30 µm, 16 µm; lift 5 µm (the defaults).
const GravureSetup kSetup;

CellPlan plan(float a, float b, float c, float d, bool lw = false) {
  return plan_cell({{a, b, c, d}, lw}, kSetup);
}

void expect_points(const CellPlan& p, std::initializer_list<std::pair<double, double>> expected) {
  ASSERT_EQ(p.count, expected.size());
  std::size_t i = 0;
  for (const auto& [x, depth] : expected) {
    EXPECT_NEAR(p.points[i].x, x, kTol) << "point " << i;
    EXPECT_NEAR(p.points[i].depth_um, depth, kTol) << "point " << i;
    ++i;
  }
}

TEST(ControlPoints, Figure3NormalCellEntryCentreExit) {
  // An even 50 % cell: centre in the middle at half the full depth, entry and exit on the
  // surface half a cell apart about it.
  expect_points(plan(0.5f, 0.5f, 0.5f, 0.5f), {{0.25, 0}, {0.5, 20}, {0.75, 0}});
  EXPECT_EQ(plan(0.5f, 0.5f, 0.5f, 0.5f).kind, CellKind::single);
  // A rising cell (20, 40, 60, 80 %): the density centre, where 1.0 of the 2.0 total lies on
  // each side, is 2/3 of the way along; the 50 % cell is placed about it.
  expect_points(plan(0.2f, 0.4f, 0.6f, 0.8f), {{2.0 / 3 - 0.25, 0}, {2.0 / 3, 20}, {2.0 / 3 + 0.25, 0}});
}

TEST(ControlPoints, Figure4DoubleFrequencyCell) {
  // 100 %, 0 %, 0 %, 100 %: 66e > 66f + 66g and 66h > 66f + 66g, so two sub-cells. Each pair
  // is 50 % dense: its sub-cell spans half of the pair's half cell (D1 = D3 = 0.5 · 0.5),
  // centred on the black value, half the full depth; the outer entry and exit take the channel
  // scaler of the black values (8 µm), the inner exit and entry lie on the surface.
  const CellPlan p = plan(1, 0, 0, 1);
  EXPECT_EQ(p.kind, CellKind::split);
  expect_points(p, {{0, 8}, {0.125, 20}, {0.25, 0}, {0.75, 0}, {0.875, 20}, {1, 8}});
}

TEST(ControlPoints, DoubleFrequencyDistancesFollowEachPairsDensity) {
  // Pair A (1.0, 0.2) is 60 % dense → exit at D1 = 0.6 · 0.5 = 0.3 from the start; pair B
  // (0.1, 0.5) is 30 % → entry at D3 = 0.3 · 0.5 = 0.15 before the end.
  const CellPlan p = plan(1.0f, 0.2f, 0.1f, 0.5f);
  ASSERT_EQ(p.kind, CellKind::split);
  EXPECT_NEAR(p.points[2].x, 0.3, 1e-7);
  EXPECT_NEAR(p.points[2].depth_um, 0, kTol);
  EXPECT_NEAR(p.points[3].x, 1 - 0.15, 1e-7);
  EXPECT_NEAR(p.points[1].depth_um, 40 * 0.6, 1e-5);  // full-cell scaler of the pair's density
  EXPECT_NEAR(p.points[4].depth_um, 40 * 0.3, 1e-5);
  EXPECT_NEAR(p.points[0].depth_um, 8 * 1.0, 1e-6);   // channel scaler of d1
  EXPECT_NEAR(p.points[5].depth_um, 8 * 0.5, 1e-6);   // channel scaler of d4
  // Centre of pair A: 0.3 of density on each side; the first quarter holds 0.25 → 0.15.
  EXPECT_NEAR(p.points[1].x, 0.15, 1e-7);
  for (int i = 1; i < 6; ++i) EXPECT_GT(p.points[i].x, p.points[i - 1].x);
}

TEST(ControlPoints, SplitNeedsBothOuterValuesStrictlyAboveTheMiddlePair) {
  EXPECT_EQ(plan(0.6f, 0.3f, 0.3f, 1).kind, CellKind::single);  // d1 = d2 + d3
  EXPECT_EQ(plan(1, 0.3f, 0.3f, 0.6f).kind, CellKind::single);  // d4 = d2 + d3
  EXPECT_EQ(plan(0.61f, 0.3f, 0.3f, 0.61f).kind, CellKind::split);
}

TEST(ControlPoints, Figure4AShiftedCell) {
  // 100, 100, 0, 0 %: a 50 % cell that the prior art would centre on the cell; here its centre
  // moves to the density centre (the end of the second value) and the cell covers exactly the
  // two black values (engraved area 75).
  const CellPlan p = plan(1, 1, 0, 0);
  EXPECT_EQ(p.kind, CellKind::single);
  expect_points(p, {{0, 0}, {0.25, 20}, {0.5, 0}});
  // And mirrored.
  expect_points(plan(0, 0, 1, 1), {{0.5, 0}, {0.75, 20}, {1, 0}});
}

TEST(ControlPoints, UnderOnePercentTheStylusStaysAboveTheSurface) {
  const CellPlan white = plan(0, 0, 0, 0);
  EXPECT_EQ(white.kind, CellKind::white);
  expect_points(white, {{0.5, -5}});
  // Total 0.875 %: still white, even though one value is 1.5 %.
  EXPECT_EQ(plan(0.005f, 0.005f, 0.005f, 0.02f).kind, CellKind::white);
  // Total 1.125 %: engraved, a tiny cell 0.01125 of a cell long.
  const CellPlan tiny = plan(0.01f, 0.01f, 0.01f, 0.015f);
  EXPECT_EQ(tiny.kind, CellKind::single);
  EXPECT_NEAR(tiny.points[2].x - tiny.points[0].x, 0.01125, 1e-7);
  EXPECT_NEAR(tiny.points[1].depth_um, 40 * 0.01125, 1e-5);
}

TEST(ControlPoints, AboveNinetyPercentEntryAndExitLieBelowTheSurface) {
  const CellPlan p = plan(0.9f, 0.95f, 0.95f, 0.92f);  // total 93 %
  EXPECT_EQ(p.kind, CellKind::channel);
  ASSERT_EQ(p.count, 3);
  EXPECT_NEAR(p.points[0].x, 0, kTol);
  EXPECT_NEAR(p.points[0].depth_um, 8 * 0.9, 1e-5);   // channel scaler of d1
  EXPECT_NEAR(p.points[2].x, 1, kTol);
  EXPECT_NEAR(p.points[2].depth_um, 8 * 0.92, 1e-5);  // channel scaler of d4
  EXPECT_NEAR(p.points[1].depth_um, 40 * 0.93, 1e-5);
  EXPECT_GT(p.points[0].depth_um, 0);
  EXPECT_GT(p.points[2].depth_um, 0);
  // Exactly 90 % is not above 90 %: entry and exit on the surface, 0.9 of a cell apart.
  const CellPlan at90 = plan(0.9f, 0.9f, 0.9f, 0.9f);
  EXPECT_EQ(at90.kind, CellKind::single);
  EXPECT_NEAR(at90.points[0].depth_um, 0, kTol);
  EXPECT_NEAR(at90.points[2].x - at90.points[0].x, 0.9, 1e-6);
  expect_points(plan(1, 1, 1, 1), {{0, 8}, {0.5, 40}, {1, 8}});
}

TEST(ControlPoints, LineWorkUsesTheLineWorkScalers) {
  expect_points(plan(1, 1, 1, 1, true), {{0, 16}, {0.5, 30}, {1, 16}});
  expect_points(plan(0.5f, 0.5f, 0.5f, 0.5f, true), {{0.25, 0}, {0.5, 15}, {0.75, 0}});
}

TEST(ControlPoints, GainAndOffsetScaleEveryEngravedDepth) {
  GravureSetup s;
  s.ct.gain = 1.2;
  s.ct.offset_um = 2;
  const CellPlan p = plan_cell({{1, 1, 1, 1}, false}, s);
  EXPECT_NEAR(p.points[1].depth_um, 2 + 1.2 * 40, kTol);
  EXPECT_NEAR(p.points[0].depth_um, 2 + 1.2 * 8, kTol);
}

TEST(ControlPoints, CentreStaysInsideItsCell) {
  // One black value at the very start: the density centre is 1/8 of the cell, and the 25 %
  // cell [0, 0.25] is centred on it.
  expect_points(plan(1, 0, 0, 0), {{0, 0}, {0.125, 10}, {0.25, 0}});
  // A faint value at the start and a dark one at the end do not split (0.2 < 0 + 0): the cell
  // is placed about the density centre and moved to stay inside the cell.
  const CellPlan p = plan(0, 0, 0.2f, 1);
  EXPECT_EQ(p.kind, CellKind::single);
  EXPECT_LE(p.points[2].x, 1 + kTol);
  EXPECT_GE(p.points[0].x, -kTol);
  EXPECT_GT(p.points[1].x, p.points[0].x);
  EXPECT_LT(p.points[1].x, p.points[2].x);
}

TEST(DensityCentre, HalfTheDensityOnEachSide) {
  const float even[4] = {1, 1, 1, 1};
  EXPECT_NEAR(density_centre(even, 4, 0, 1), 0.5, kTol);
  const float ends[4] = {1, 0, 0, 1};  // half reached at 0.25, held to 0.75: the middle
  EXPECT_NEAR(density_centre(ends, 4, 0, 1), 0.5, kTol);
  const float left[2] = {1, 0.2f};
  EXPECT_NEAR(density_centre(left, 2, 0, 0.5), 0.15, 1e-7);
  const float none[4] = {0, 0, 0, 0};
  EXPECT_NEAR(density_centre(none, 4, 0, 1), 0.5, kTol);
}

}  // namespace
}  // namespace mark
