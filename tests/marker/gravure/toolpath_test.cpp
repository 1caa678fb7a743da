// The curve fitter and the synchronised toolpath: the cubic spline passes through every control
// point and is C² (Eigen's solve against the tridiagonal equations), the windowed stream equals
// the whole-path solution, and stylus sample n lands in cell ⌊n·f_cell/f_s⌋ — 32 samples a cell
// at 6.25 kHz.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "driver/sim/stylus_cells.hpp"
#include "marker/gravure/cubic_spline.hpp"
#include "marker/gravure/stylus_toolpath.hpp"

namespace mark {
namespace {

TEST(CubicSpline, PassesThroughEveryKnotWithNaturalEnds) {
  const std::vector<double> x{0, 0.3, 0.5, 1.2, 1.25, 2, 3.5};
  const std::vector<double> y{1, -2, 4, 0.5, 0.7, -3, 2};
  const CubicSpline s(x, y);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(s(x[i]), y[i], 1e-12) << i;
  EXPECT_DOUBLE_EQ(s.second_derivatives().front(), 0);
  EXPECT_DOUBLE_EQ(s.second_derivatives().back(), 0);
  // C¹ at every interior knot: slopes from both sides agree.
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    const double h = 1e-6;
    const double left = (s(x[i]) - s(x[i] - h)) / h, right = (s(x[i] + h) - s(x[i])) / h;
    EXPECT_NEAR(left, right, 1e-3 * (1 + std::abs(left))) << i;
  }
}

TEST(CubicSpline, SolvesTheTridiagonalEquations) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> step(0.01, 1), value(-50, 50);
  std::vector<double> x{0}, y{value(rng)};
  for (int i = 0; i < 200; ++i) {
    x.push_back(x.back() + step(rng));
    y.push_back(value(rng));
  }
  const CubicSpline s(x, y);
  const auto& m = s.second_derivatives();
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    const double lhs = h0 * m[i - 1] + 2 * (h0 + h1) * m[i] + h1 * m[i + 1];
    const double rhs = 6 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
    EXPECT_NEAR(lhs, rhs, 1e-9 * (1 + std::abs(rhs))) << i;
  }
}

TEST(CubicSpline, StraightLineStaysStraight) {
  const CubicSpline s({0, 1, 1.5, 4}, {1, 3, 4, 9});
  for (double x = 0; x <= 4; x += 0.05) EXPECT_NEAR(s(x), 1 + 2 * x, 1e-12);
}

TEST(Synchronisation, SampleToCellAndPosition) {
  // 6.25 kHz: the seed's 32 samples a cell.
  EXPECT_EQ(first_sample_of_cell(1, 6250), 32u);
  const CellPosition p = cell_position(32 * 7 + 16, 6250);
  EXPECT_EQ(p.cell, 7u);
  EXPECT_DOUBLE_EQ(p.fraction, 0.5);
  // 3.2 kHz: 62.5 samples a cell, cells of 63 and 62 samples alternately.
  EXPECT_EQ(first_sample_of_cell(1, 3200), 63u);
  EXPECT_EQ(first_sample_of_cell(2, 3200), 125u);
  EXPECT_EQ(cell_position(125, 3200).cell, 2u);
  EXPECT_DOUBLE_EQ(cell_position(125, 3200).fraction, 0.0);
  EXPECT_EQ(cell_position(124, 3200).cell, 1u);
  for (std::uint64_t c = 0; c < 1000; ++c) EXPECT_EQ(cell_of_sample(first_sample_of_cell(c, 4321), 4321), c);
}

// The toolpath through a row of cells, sampled at 32 samples a cell: every control point of the
// seed's figures falls on a sample (multiples of 1/32), so the samples there must equal it.
TEST(StylusToolpath, PassesThroughEveryControlPoint) {
  const std::vector<CellValues> cells{
      {{0, 0, 0, 0}, false},           // white
      {{0.5f, 0.5f, 0.5f, 0.5f}, false},  // FIG. 3
      {{0, 0, 0, 0}, false},
      {{1, 0, 0, 1}, false},           // FIG. 4
      {{0, 0, 0, 0}, false},
      {{1, 1, 0, 0}, false},           // FIG. 4A
      {{0, 0, 0, 0}, false},
      {{1, 1, 1, 1}, true},            // LW channel cell
      {{0, 0, 0, 0}, false}};
  CellList source(cells);
  const GravureSetup setup;
  StylusToolpath toolpath(source, {setup, 6250, 0});
  ASSERT_EQ(toolpath.total_samples(), cells.size() * 32);
  std::vector<double> depth(toolpath.total_samples());
  ASSERT_EQ(toolpath.next(depth), depth.size());
  EXPECT_EQ(toolpath.next(depth), 0u);
  std::size_t checked = 0;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const CellPlan plan = plan_cell(cells[c], setup);
    for (std::uint8_t k = 0; k < plan.count; ++k) {
      const double n = (c + plan.points[k].x) * 32;
      ASSERT_NEAR(n, std::round(n), 1e-9) << "control point off the sample grid";
      const auto i = static_cast<std::size_t>(std::llround(n));
      if (i >= depth.size()) continue;
      EXPECT_NEAR(depth[i], plan.points[k].depth_um, 1e-9) << "cell " << c << " point " << int(k);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 1u + 3 + 1 + 6 + 1 + 3 + 1 + 3 + 1);
  EXPECT_EQ(toolpath.counts().white, 5u);
  EXPECT_EQ(toolpath.counts().single, 2u);
  EXPECT_EQ(toolpath.counts().split, 1u);
  EXPECT_EQ(toolpath.counts().channel, 1u);
  EXPECT_EQ(toolpath.counts().line_work, 1u);
}

TEST(StylusToolpath, AdvanceShiftsTheToolpathEarlier) {
  std::vector<CellValues> cells(20, CellValues{{0.3f, 0.7f, 0.6f, 0.2f}, false});
  CellList a(cells), b(cells);
  const GravureSetup setup;
  StylusToolpath plain(a, {setup, 6250, 0}), early(b, {setup, 6250, 5});
  std::vector<double> p(640), e(640);
  plain.next(p);
  early.next(e);
  for (std::size_t n = 0; n + 5 < p.size(); ++n) EXPECT_NEAR(e[n], p[n + 5], 1e-9);
}

TEST(StylusToolpath, StartsAndEndsLiftedAboveTheSurface) {
  std::vector<CellValues> cells(3, CellValues{{1, 1, 1, 1}, false});
  CellList source(cells);
  GravureSetup setup;
  setup.lift_um = 7;
  StylusToolpath toolpath(source, {setup, 5000, 0});
  std::vector<double> d(toolpath.total_samples());
  toolpath.next(d);
  EXPECT_EQ(d.size(), 120u);                // 40 samples a cell at 5 kHz
  EXPECT_NEAR(d.front(), 8, 1e-9);          // the channel entry of the first black cell
  EXPECT_NEAR(d[20], 40, 1e-9);             // its centre
  EXPECT_GT(d.back(), 0);                   // still in the channel at the last sample
  // Between the channel points the spline came down from the lift point at x = −0.5 and goes
  // back up to the one at x = 3.5: it is lifted there.
  CellList again(cells);
  StylusToolpath early(again, {setup, 5000, -30});  // sample 0 shows x = −0.75
  std::vector<double> e(40);
  early.next(e);
  EXPECT_NEAR(e[10], -7, 1e-9);             // x = −0.5: the lift knot
}

}  // namespace
}  // namespace mark
