// Quality figures on synthetic marks with known answers.
#include "driver/sim/quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace mark {
namespace {

// Polyline from a to b with points ≤ step apart.
std::vector<Vec2> dense(Vec2 a, Vec2 b, double step = 0.005) {
  const int n = std::max(1, static_cast<int>(std::ceil(norm(b - a) / step)));
  std::vector<Vec2> p;
  for (int i = 0; i <= n; ++i) p.push_back(a + (static_cast<double>(i) / n) * (b - a));
  return p;
}

// A perfect constant-speed mark of the polyline: dose proportional to length.
void mark_evenly(DoseRaster& dose, const std::vector<Vec2>& line, double per_mm = 1.0) {
  for (std::size_t i = 1; i < line.size(); ++i)
    dose.deposit_segment(line[i - 1], line[i], per_mm * norm(line[i] - line[i - 1]));
}

struct Case {
  std::vector<std::vector<Vec2>> intended;
  LitPaths lit;
  DoseRaster dose;
  // mark_evenly leaves 1 s of full power per mm: the nominal of a pen at 100 % and 1 mm/s.
  MarkIntent intent = [] {
    MarkIntent m;
    m.nominal_dose_s_per_mm = 1.0;
    return m;
  }();
  Quality eval() const { return evaluate_quality(intended, lit, dose, intent); }
};

TEST(Quality, PerfectMarkScoresPerfectly) {
  Case c;
  c.intended = {dense({0, 0}, {2, 0}), dense({0, 0.5}, {1, 1.5})};
  for (const auto& l : c.intended) {
    c.lit.runs.push_back(l);
    mark_evenly(c.dose, l);
  }
  const Quality q = c.eval();
  EXPECT_LT(q.max_deviation_um, 1e-6);
  EXPECT_LT(q.rms_deviation_um, 1e-6);
  EXPECT_DOUBLE_EQ(q.coverage, 1.0);
  EXPECT_NEAR(q.dose_ratio_max, 1.0, 0.03);
  EXPECT_LT(q.overshoot_um, 1e-6);
  EXPECT_EQ(q.lit_points, c.intended[0].size() + c.intended[1].size());
}

TEST(Quality, DosePerMmIsTheLeastDosedStrokesShareOfTheNominal) {
  // Three strokes at the nominal, one at 40 % of it: the median of all (and so the dose ratio's
  // denominator) stays at the nominal; the figure names the thin stroke.
  Case c;
  c.intended = {dense({0, 0}, {2, 0}), dense({0, 1}, {2, 1}), dense({0, 2}, {2, 2}), dense({0, 3}, {2, 3})};
  for (std::size_t i = 0; i < c.intended.size(); ++i) {
    c.lit.runs.push_back(c.intended[i]);
    mark_evenly(c.dose, c.intended[i], i == 2 ? 0.4 : 1.0);
  }
  const Quality q = c.eval();
  EXPECT_NEAR(q.dose_per_mm_fraction, 0.4, 0.01);
  EXPECT_DOUBLE_EQ(q.coverage, 1.0);
  // Twice the nominal for the pen: every stroke at half of it.
  c.intent.nominal_dose_s_per_mm = 2.0;
  EXPECT_NEAR(c.eval().dose_per_mm_fraction, 0.2, 0.005);
  // No pulse figures given: no gap, and no spot to judge one against.
  EXPECT_DOUBLE_EQ(q.pulse_gap_max_um, 0);
  EXPECT_DOUBLE_EQ(q.spot_diameter_um, 0);
}

// The medians are taken along the stroke's length, not over its points: a caller that cuts part
// of a stroke finer (a curve in 1 µm pieces beside a line left whole) does not tip them. 40 % of
// the stroke at the nominal, 60 % at twice it: the stroke's median is twice the nominal however
// the 40 % is cut (by count of points it would be the nominal once that part has most of them).
TEST(Quality, MediansAreAlongTheLengthNotOverThePointsGiven) {
  const auto figures = [](double first_step) {
    Case c;
    std::vector<Vec2> line = dense({0, 0}, {0.8, 0}, first_step);
    const std::vector<Vec2> rest = dense({0.8, 0}, {2, 0}, 0.005);
    line.insert(line.end(), rest.begin() + 1, rest.end());
    c.intended = {line};
    c.lit.runs.push_back(line);
    mark_evenly(c.dose, dense({0, 0}, {0.8, 0}), 1.0);
    mark_evenly(c.dose, dense({0.8, 0}, {2, 0}), 2.0);
    return c.eval();
  };
  const Quality even = figures(0.005), fine = figures(0.001);
  EXPECT_NEAR(even.dose_per_mm_fraction, 2.0, 0.05);
  EXPECT_NEAR(fine.dose_per_mm_fraction, even.dose_per_mm_fraction, 0.01 * even.dose_per_mm_fraction);
  EXPECT_NEAR(fine.dose_ratio_max, even.dose_ratio_max, 0.01 * even.dose_ratio_max);
  EXPECT_NEAR(fine.coverage, even.coverage, 1e-9);
}

TEST(Quality, WorseOfTakesEachFiguresWorse) {
  Quality a, b;
  a.max_deviation_um = 3, b.max_deviation_um = 7;
  a.coverage = 0.99, b.coverage = 1.0;
  a.pulse_gap_max_um = 10, a.spot_diameter_um = 40;  // a quarter spot
  b.pulse_gap_max_um = 10, b.spot_diameter_um = 20;  // half a spot: the worse gap
  a.dose_per_mm_fraction = 0.9, b.dose_per_mm_fraction = 1.0;
  a.lit_points = 5, b.lit_points = 9;
  const Quality w = worse_of(a, b);
  EXPECT_EQ(w.max_deviation_um, 7);
  EXPECT_EQ(w.coverage, 0.99);
  EXPECT_EQ(w.spot_diameter_um, 20);
  EXPECT_EQ(w.dose_per_mm_fraction, 0.9);
  EXPECT_EQ(w.lit_points, 5u);
}

TEST(Quality, ParallelOffsetGivesDeviationAndCoverageByRadius) {
  for (double off_um : {8.0, 12.0, 20.0}) {
    Case c;
    c.intended = {dense({0, 0}, {2, 0})};
    c.lit.runs = {dense({0, off_um * 1e-3}, {2, off_um * 1e-3})};
    mark_evenly(c.dose, c.lit.runs[0]);
    const Quality q = c.eval();
    EXPECT_NEAR(q.max_deviation_um, off_um, 1e-6);
    EXPECT_NEAR(q.rms_deviation_um, off_um, 1e-6);
    EXPECT_DOUBLE_EQ(q.coverage, off_um <= 10 ? 1.0 : 0.0) << off_um;
  }
}

// A lit run is measured against the stroke it marks (the one nearest to most of its points): a
// beam that leaves its stroke and runs on along a neighbouring one 50 µm away is 50 µm off,
// although every point it passed lies on some stroke.
TEST(Quality, DeviationIsAgainstTheStrokeTheRunMarks) {
  Case c;
  c.intended = {dense({0, 0}, {2, 0}), dense({0, 0.05}, {2, 0.05})};
  std::vector<Vec2> run = dense({0, 0}, {1.2, 0});
  for (const Vec2& p : dense({1.2, 0.05}, {2, 0.05})) run.push_back(p);
  c.lit.runs = {run};
  mark_evenly(c.dose, run);
  Quality q = c.eval();
  EXPECT_NEAR(q.max_deviation_um, 50, 1e-6);
  // Marked as two runs, one per stroke, the same points are on their strokes.
  c.lit.runs = {dense({0, 0}, {1.2, 0}), dense({1.2, 0.05}, {2, 0.05})};
  q = c.eval();
  EXPECT_LT(q.max_deviation_um, 1e-6);
}

TEST(Quality, CoverageIsTheShareOfStrokeLengthNearALitPath) {
  Case c;
  c.intended = {dense({0, 0}, {2, 0})};
  c.lit.runs = {dense({0, 0}, {1, 0})};
  mark_evenly(c.dose, c.lit.runs[0]);
  // 1 mm lit plus the 10 µm the coverage radius reaches past its end.
  EXPECT_NEAR(c.eval().coverage, 1.010 / 2.0, 0.003);
}

TEST(Quality, OvershootPastAnOpenStrokeEnd) {
  Case c;
  c.intended = {dense({0, 0}, {2, 0})};
  c.lit.runs = {dense({-0.03, 0}, {2.05, 0})};
  mark_evenly(c.dose, c.lit.runs[0]);
  const Quality q = c.eval();
  EXPECT_NEAR(q.overshoot_um, 50, 0.01);
  EXPECT_NEAR(q.max_deviation_um, 50, 0.01);
  EXPECT_DOUBLE_EQ(q.coverage, 1.0);
}

TEST(Quality, ClosedStrokeHasNoEndsToOvershoot) {
  Case c;
  std::vector<Vec2> square;
  for (auto [a, b] : {std::pair<Vec2, Vec2>{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{1, 1}, {0, 1}},
                      {{0, 1}, {0, 0}}}) {
    auto side = dense(a, b);
    square.insert(square.end(), side.begin() + (square.empty() ? 0 : 1), side.end());
  }
  c.intended = {square};
  c.lit.runs = {square};
  c.lit.runs[0].push_back({0.03, 0});  // runs on past the closing point, along the first side
  mark_evenly(c.dose, square);
  const Quality q = c.eval();
  EXPECT_EQ(q.overshoot_um, 0.0);
  EXPECT_LT(q.max_deviation_um, 1e-6);
}

TEST(Quality, BurnInShowsInTheDoseRatio) {
  Case c;
  c.intended = {dense({0, 0}, {2, 0})};
  c.lit.runs = c.intended;
  mark_evenly(c.dose, c.intended[0]);
  mark_evenly(c.dose, dense({0.9, 0}, {1.1, 0}), 2.0);  // three times the dose over 0.2 mm
  EXPECT_NEAR(c.eval().dose_ratio_max, 3.0, 0.05);
}

TEST(Quality, CrossingsAndEndsAreNotBurnIn) {
  // Where two strokes cross, the ideal mark doubles its dose too; at stroke ends it halves.
  Case c;
  c.intended = {dense({0, 0}, {2, 2}), dense({0, 2}, {2, 0}), dense({3, 0}, {3, 0.3})};
  for (const auto& l : c.intended) {
    c.lit.runs.push_back(l);
    mark_evenly(c.dose, l);
  }
  EXPECT_NEAR(c.eval().dose_ratio_max, 1.0, 0.05);
}

TEST(Quality, FarStrayLightIsMeasuredExactly) {
  Case c;
  c.intended = {dense({0, 0}, {1, 0})};
  c.lit.runs = {c.intended[0], {{0.5, 5.0}}};  // a lit dot 5 mm away
  mark_evenly(c.dose, c.intended[0]);
  EXPECT_NEAR(c.eval().max_deviation_um, 5000, 1e-6);
}

TEST(Quality, PreparedReferenceGivesTheSameFiguresAndChecksThePixel) {
  Case c;
  c.intended = {dense({0, 0}, {2, 0}), dense({0, 1}, {1, 1})};
  c.lit.runs = {dense({0, 0.004}, {2.03, 0.004})};
  mark_evenly(c.dose, c.lit.runs[0]);
  const QualityReference ref(c.intended);
  const Quality a = ref.evaluate(c.lit, c.dose, c.intent), b = c.eval();
  EXPECT_EQ(a.max_deviation_um, b.max_deviation_um);
  EXPECT_EQ(a.coverage, b.coverage);
  EXPECT_EQ(a.dose_ratio_max, b.dose_ratio_max);
  EXPECT_EQ(a.overshoot_um, b.overshoot_um);
  EXPECT_NEAR(a.coverage, 2.0 / 3.0, 0.01);  // the second stroke was never lit
  EXPECT_THROW(ref.evaluate(c.lit, DoseRaster(0.01), c.intent), std::invalid_argument);
}

TEST(Quality, NothingLitHasNoCoverage) {
  Case c;
  c.intended = {dense({0, 0}, {1, 0})};
  const Quality q = c.eval();
  EXPECT_EQ(q.lit_points, 0u);
  EXPECT_EQ(q.coverage, 0.0);
}

}  // namespace
}  // namespace mark
