// The toolpath curve cannot overshoot (issue 23): between any two control points the toolpath
// stays within their depths — for the curve alone on random knots, for whole random tracks of
// cells, and for the minimal case of the issue (a single cell's exit on the surface a hair
// before the next channel cell's entry), which the natural spline swung to −335 … +482 µm.
#include "marker/gravure/monotone_curve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "marker/gravure/cubic_spline.hpp"
#include "marker/gravure/gravure_job.hpp"
#include "marker/gravure/stylus_toolpath.hpp"

namespace mark {
namespace {

// Every sample of a curve over all knots, checked piece by piece against the two knots' range.
template <class Curve>
double worst_overshoot(Curve&& curve, const std::vector<double>& x, const std::vector<double>& y, int per_piece = 50) {
  double worst = 0;
  for (std::size_t j = 0; j + 1 < x.size(); ++j) {
    const double lo = std::min(y[j], y[j + 1]), hi = std::max(y[j], y[j + 1]);
    for (int k = 0; k <= per_piece; ++k) {
      const double v = curve(x[j] + (x[j + 1] - x[j]) * k / per_piece);
      worst = std::max({worst, v - hi, lo - v});
    }
  }
  return worst;
}

TEST(MonotoneCurve, PassesThroughTheKnotsAndKeepsStraightLinesStraight) {
  MonotoneCurve c;
  const std::vector<double> x{0, 1, 1.5, 4}, y{1, 3, 4, 9};
  for (std::size_t i = 0; i < x.size(); ++i) c.push(x[i], y[i]);
  c.finish();
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(c.eval(x[i]), y[i], 1e-12);
  // Interior knots on one line (slope 2): the harmonic mean of equal secants is that secant.
  MonotoneCurve line;
  for (double t : {0.0, 0.3, 1.0, 2.5, 3.0, 4.0}) line.push(t, 2 * t + 1);
  line.finish();
  EXPECT_NEAR(line.eval(0.65), 2 * 0.65 + 1, 1e-12);
  EXPECT_NEAR(line.eval(2.0), 5, 1e-12);
}

TEST(MonotoneCurve, SlopeIsZeroAtExtremaAndTheHarmonicMeanElsewhere) {
  EXPECT_EQ(monotone_slope(1, 2, 1, -3), 0);
  EXPECT_EQ(monotone_slope(1, 0, 1, 5), 0);
  // Equal intervals: 2 / (1/d0 + 1/d1), SciPy's pchip for x = 0, 1, 2 and y = 0, 1, 4.
  EXPECT_NEAR(monotone_slope(1, 1, 1, 3), 1.5, 1e-12);
}

TEST(MonotoneCurve, NeverLeavesTheRangeOfTwoKnotsOnRandomKnots) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> gap(1e-6, 1), depth(-10, 50);
  std::vector<double> x{0}, y{0};
  for (int i = 0; i < 5000; ++i) {
    x.push_back(x.back() + (i % 7 == 0 ? gap(rng) * 1e-3 : gap(rng)));  // some knots nearly coincide
    y.push_back(depth(rng));
  }
  MonotoneCurve c;
  for (std::size_t i = 0; i < x.size(); ++i) c.push(x[i], y[i]);
  c.finish();
  EXPECT_LT(worst_overshoot([&](double t) { return c.eval(t); }, x, y), 1e-9);
  // The natural spline through the same knots does overshoot (the defect this curve replaces).
  EXPECT_GT(worst_overshoot(CubicSpline(x, y), x, y), 10);
}

TEST(MonotoneCurve, StreamsWithBoundedLookAheadAndRefusesBadKnots) {
  MonotoneCurve c;
  c.push(0, 0);
  c.push(1, 1);
  EXPECT_EQ(c.committed_x(), -INFINITY);
  c.push(2, 0);
  EXPECT_EQ(c.committed_x(), 1);  // piece [0, 1] needs the slope at 1, which needs knot 2
  EXPECT_NO_THROW(c.eval(0.5));
  EXPECT_THROW(c.eval(1.5), std::logic_error);
  EXPECT_THROW(c.push(2, 1), std::invalid_argument);
  EXPECT_THROW(c.push(NAN, 1), std::invalid_argument);
  c.finish();
  EXPECT_NEAR(c.eval(1.5), 0.5, 1e-12);  // symmetric piece between an extremum and the flat end
  EXPECT_EQ(c.eval(5), 0);
  EXPECT_THROW(c.push(3, 1), std::logic_error);
}

TEST(MonotoneCurve, LongStreamsMatchAShortEvaluationAfterCompaction) {
  MonotoneCurve c;
  std::vector<double> x, y;
  for (int i = 0; i < 30000; ++i) {
    x.push_back(i * 0.25);
    y.push_back(std::sin(i * 0.3) * 20);
  }
  for (std::size_t i = 0; i < x.size(); ++i) c.push(x[i], y[i]);
  c.finish();
  EXPECT_LT(worst_overshoot([&](double t) { return c.eval(t); }, x, y, 4), 1e-9);
  EXPECT_EQ(c.knots(), x.size());
}

// The toolpath of a list of cells, sampled at the stylus clock.
std::vector<double> toolpath_of(const std::vector<CellValues>& cells, const GravureSetup& setup) {
  CellList source(cells);
  StylusToolpath toolpath(source, {setup, 6250, 0});
  std::vector<double> d(toolpath.total_samples());
  toolpath.next(d);
  return d;
}

// The minimal case: single cells with their density towards the end, so the exit lands on the surface just before the next (channel) cell's entry
// 8 µm down — every such cell of a sweep that puts the exit 0.001 … 0.002 cell before the
// boundary (outside the 1e−3 merge).
std::vector<CellValues> singles_beside_the_boundary(const GravureSetup& setup) {
  std::vector<CellValues> found;
  // {0, b, c, 1} on 8-bit grey levels: the shape that puts the exit a hair inside the cell.
  for (int b = 0; b <= 255; b += 3)
    for (int c = 0; c <= 255; c += 3) {
      const CellValues single{{0.0f, b / 255.0f, c / 255.0f, 1.0f}, false};
      const CellPlan plan = plan_cell(single, setup);
      if (plan.kind != CellKind::single) continue;
      const double exit = plan.points[plan.count - 1].x;
      if (exit >= 0.998 && exit < 0.999) found.push_back(single);
    }
  return found;
}

TEST(StylusToolpath, ASingleCellBesideChannelCellsCutsNoDeeperThanTheFullCell) {
  const GravureSetup setup;
  const std::vector<CellValues> singles = singles_beside_the_boundary(setup);
  ASSERT_GT(singles.size(), 10u);
  const CellValues black{{1, 1, 1, 1}, false};
  double deepest = 0, highest = 0, natural_deepest = 0;
  for (const CellValues& single : singles) {
    const std::vector<double> d = toolpath_of({black, black, single, black, black}, setup);
    deepest = std::max(deepest, *std::max_element(d.begin(), d.end()));
    highest = std::min(highest, *std::min_element(d.begin(), d.end()));
    // The seed's natural spline through the same control points, for the record.
    std::vector<double> x{-0.5}, y{-setup.lift_um};
    int cell = 0;
    for (const CellValues& c : {black, black, single, black, black}) {
      const CellPlan p = plan_cell(c, setup);
      for (std::uint8_t k = 0; k < p.count; ++k) {
        const double px = cell + p.points[k].x;
        if (px - x.back() < 1e-3) continue;  // the toolpath's merge (here: equal depths)
        x.push_back(px);
        y.push_back(p.points[k].depth_um);
      }
      ++cell;
    }
    x.push_back(5.5);
    y.push_back(-setup.lift_um);
    const CubicSpline natural(x, y);
    for (double t = 0; t < 5; t += 1.0 / 32) natural_deepest = std::max(natural_deepest, natural(t));
  }
  EXPECT_LE(deepest, setup.ct.full_cell_depth(1) + 1e-9);
  EXPECT_GE(highest, -setup.lift_um - 1e-9);
  EXPECT_GT(natural_deepest, 2 * setup.ct.full_cell_depth(1));  // what the natural spline did
}

// The same minimal case as an image (28 × 4 px: one track of seven cells) through the whole
// job on the simulated head, filters on and off: the deepest cut stays at the full cell.
TEST(GravureJob, MinimalSingleCellBesideChannelsCutsNoDeeperThanTheFullCell) {
  const GravureSetup setup;
  const CellValues single = singles_beside_the_boundary(setup).front();
  GrayImage img{28, 4, std::vector<float>(28 * 4, 0.0f)};  // black: full density
  for (int y = 0; y < 4; ++y)
    for (int k = 0; k < 4; ++k) img.pixels[static_cast<std::size_t>(y) * 28 + 8 + k] = 1 - single.density[k];
  for (FilterChoice filters : {FilterChoice::nominal, FilterChoice::off}) {
    GravureJobSpec spec;
    spec.image = img;
    spec.filters = filters;
    const GravureReport r = run_gravure_job(spec);
    SCOPED_TRACE(std::string(to_string(filters)));
    ASSERT_EQ(r.cells, 7u);
    EXPECT_EQ(r.counts.single, 1u);
    EXPECT_EQ(r.counts.channel, 6u);
    if (filters == FilterChoice::off) {
      // The toolpath (the drive, without filters) never asks for more than the full cell; the
      // bare head still rings on the channel's 8 ↔ 40 µm steps (ζ 0.06), by less than half.
      EXPECT_LE(r.filtered.drive_peak_um, r.full_cell_depth_um + 1e-6);
      EXPECT_LE(r.filtered.max_cut_um, 1.5 * r.full_cell_depth_um);
    } else {
      // Filtered, the head follows the toolpath within about a micrometre.
      EXPECT_LE(r.filtered.max_cut_um, r.full_cell_depth_um + 1.0);
      EXPECT_LT(r.filtered.depth_error_vs_cells.max_um, 1.5);
    }
  }
}

TEST(StylusToolpath, StaysWithinTheControlPointsOfRandomTracks) {
  // Property: over random tracks of every kind of cell, each toolpath sample lies within the
  // depths of the two control points around it.
  std::mt19937 rng(2323);
  std::uniform_real_distribution<float> u(0, 1);
  const GravureSetup setup;
  for (int track = 0; track < 40; ++track) {
    std::vector<CellValues> cells(60);
    for (auto& c : cells) {
      const int kind = static_cast<int>(u(rng) * 4);
      for (auto& v : c.density)
        v = kind == 0 ? u(rng) : kind == 1 ? (u(rng) < 0.5f ? 0.0f : 1.0f) : kind == 2 ? 0.9f + 0.1f * u(rng) : 0.0f;
      c.line_work = u(rng) < 0.3f;
    }
    // The control points as the toolpath merges them (within 1e−3 cell), lifted at both ends.
    std::vector<double> x{-0.5}, y{-setup.lift_um};
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const CellPlan p = plan_cell(cells[i], setup);
      for (std::uint8_t k = 0; k < p.count; ++k) {
        const double px = static_cast<double>(i) + p.points[k].x;
        if (px - x.back() < 1e-3) {
          x.back() = (x.back() + px) / 2;
          y.back() = (y.back() + p.points[k].depth_um) / 2;
        } else {
          x.push_back(px);
          y.push_back(p.points[k].depth_um);
        }
      }
    }
    x.push_back(static_cast<double>(cells.size()) + 0.5);
    y.push_back(-setup.lift_um);
    const std::vector<double> d = toolpath_of(cells, setup);
    std::size_t j = 0;
    for (std::size_t n = 0; n < d.size(); ++n) {
      const double at = static_cast<double>(n) / 32;
      while (j + 2 < x.size() && at > x[j + 1]) ++j;
      const double lo = std::min(y[j], y[j + 1]), hi = std::max(y[j], y[j + 1]);
      ASSERT_GE(d[n], lo - 1e-9) << "track " << track << " sample " << n;
      ASSERT_LE(d[n], hi + 1e-9) << "track " << track << " sample " << n;
    }
  }
}

}  // namespace
}  // namespace mark
