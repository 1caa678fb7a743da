// The stepper gantry's time model against hand-computed trapezoidal and triangular moves, step
// quantisation, the slower axis deciding, and what a run of a plan reports.
#include <gtest/gtest.h>

#include <cmath>

#include "base/error.hpp"
#include "marker/peen/gantry.hpp"
#include "marker/peen/gantry_run.hpp"
#include "marker/peen/move_cost.hpp"

namespace mark {
namespace {

GantryConfig round_numbers() {
  GantryConfig g;
  g.x = {100.0, 100.0, 1000.0};  // 0.01 mm steps, 100 mm/s, 1000 mm/s²: full speed after 10 mm
  g.y = {50.0, 50.0, 500.0};     // 0.02 mm steps, 50 mm/s, 500 mm/s²: full speed after 5 mm
  g.strike_s = 0.004;
  return g;
}

TEST(PeenGantry, TrapezoidalAndTriangularMovesByHand) {
  const AxisLimits x = round_numbers().x;
  // 30 mm: accelerate 0.1 s over 5 mm, cruise 20 mm at 100 mm/s (0.2 s), brake 0.1 s → 0.4 s.
  AxisProfile p = axis_profile(3000, x);
  EXPECT_DOUBLE_EQ(p.distance_mm, 30.0);
  EXPECT_DOUBLE_EQ(p.peak_speed_mm_s, 100.0);
  EXPECT_DOUBLE_EQ(p.accel_s, 0.1);
  EXPECT_DOUBLE_EQ(p.cruise_s, 0.2);
  EXPECT_DOUBLE_EQ(p.duration_s(), 0.4);
  // 2.5 mm: a triangle, 1.25 mm each way: t = √(2·1.25/1000) = 0.05 s up, 0.05 s down, peak 50 mm/s.
  p = axis_profile(-250, x);
  EXPECT_EQ(p.steps, -250);
  EXPECT_NEAR(p.accel_s, 0.05, 1e-15);
  EXPECT_NEAR(p.peak_speed_mm_s, 50.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.cruise_s, 0.0);
  EXPECT_NEAR(p.duration_s(), 0.1, 1e-15);
  // Exactly v²/a = 10 mm: the triangle and the trapezoid agree, 0.2 s.
  EXPECT_NEAR(axis_time_s(10.0, x), 0.2, 1e-15);
  EXPECT_NEAR(axis_time_s(10.0 - 1e-9, x), 0.2, 1e-9);
  EXPECT_DOUBLE_EQ(axis_time_s(0.0, x), 0.0);
  // The defaults: 0.5 mm dot pitch at 3000 mm/s² is 2·√(0.5/3000) = 25.8 ms.
  EXPECT_NEAR(axis_time_s(0.5, GantryConfig{}.x), 2 * std::sqrt(0.5 / 3000.0), 1e-15);
}

TEST(PeenGantry, SlowerAxisEndsTheMoveAndPositionsAreSteps) {
  const GantryConfig g = round_numbers();
  // (3, 4) mm: x takes 2·√(3/1000) = 0.10954 s, y 2·√(4/500) = 0.17889 s → y decides.
  const StepPoint a = to_steps(Point(0, 0), g), b = to_steps(Point(3, 4), g);
  EXPECT_EQ(b, (StepPoint{300, 200}));
  EXPECT_NEAR(move_time_s(a, b, g), 2 * std::sqrt(4.0 / 500.0), 1e-15);
  // (12, 1) mm: x trapezoid 12/100 + 100/1000 = 0.22 s beats y's 2·√(1/500) = 0.0894 s.
  EXPECT_NEAR(move_time_s(a, to_steps(Point(12, 1), g), g), 0.22, 1e-15);
  // Quantisation: 0.004 mm is less than half an x step, 0.006 mm more.
  EXPECT_EQ(to_steps(Point(0.004, 0.011), g), (StepPoint{0, 1}));
  EXPECT_EQ(to_steps(Point(0.006, -0.011), g), (StepPoint{1, -1}));
  EXPECT_EQ(to_mm(StepPoint{1, -1}, g), Point(0.01, -0.02));
}

TEST(PeenGantry, RunReportsTimeTravelStrikesAndReversals) {
  const GantryConfig g = round_numbers();
  PeenPlan plan;
  plan.home_mm = Point(0, 0);
  // Home → strike (2.5, 0) → turn at (2.5, 5) → strike (0, 5) → strike again there (no move)
  // → home. Moves: +x 2.5; +y 5; −x 2.5; −y 5.
  plan.stops = {{Point(2.5, 0), 0}, {Point(2.5, 5), std::nullopt}, {Point(0, 5), 1}, {Point(0, 5), 2}};
  const GantryReport r = run_plan(plan, g, true);
  // x 2.5 mm: triangle 2·√(2.5/1000) = 0.1 s; y 5 mm = v²/a: 2·√(5/500) = 0.2 s.
  EXPECT_EQ(r.moves, 4u);
  EXPECT_EQ(r.strikes, 3u);
  EXPECT_NEAR(r.move_s, 2 * 0.1 + 2 * 0.2, 1e-12);
  EXPECT_NEAR(r.strike_s, 0.012, 1e-15);
  EXPECT_NEAR(r.total_s, r.move_s + r.strike_s, 1e-15);
  EXPECT_NEAR(r.travel_mm, 15.0, 1e-12);
  EXPECT_EQ(r.reversals, 2u);  // x: + then −; y: + then −
  // The log has the four moves and the strike made without moving.
  ASSERT_EQ(r.log.size(), 5u);
  EXPECT_EQ(r.log[3].duration_s, 0.0);
  EXPECT_EQ(r.log[3].strike, std::optional<std::size_t>(2));
  EXPECT_EQ(r.log[4].to, (StepPoint{0, 0}));
}

TEST(PeenGantry, PlannerCostIsTheSimulatorsMoveTime) {
  for (double steps_per_mm : {40.0, 2e5}) {  // tabulated, and too fine to tabulate
    GantryConfig g = round_numbers();
    g.x.steps_per_mm = steps_per_mm;
    const std::vector<StepPoint> pts = {to_steps(Point(0, 0), g), to_steps(Point(12.3, -4.1), g),
                                        to_steps(Point(-7.7, 0.3), g)};
    const MoveCost cost(pts, g);
    for (std::size_t a = 0; a < pts.size(); ++a)
      for (std::size_t b = 0; b < pts.size(); ++b)
        EXPECT_DOUBLE_EQ(cost(a, b), move_time_s(pts[a], pts[b], g)) << steps_per_mm;
  }
}

TEST(PeenGantry, ImpossibleParametersAreRefused) {
  GantryConfig g;
  g.y.accel_mm_s2 = 0;
  try {
    g.validate();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("y acceleration"), std::string::npos) << e.what();
  }
  g = GantryConfig{};
  g.strike_s = -1;
  EXPECT_THROW(g.validate(), InputError);
  g = GantryConfig{};
  g.x.steps_per_mm = std::nan("");
  EXPECT_THROW(run_plan(PeenPlan{}, g), InputError);
}

}  // namespace
}  // namespace mark
