// The delays strategy (the RTC model): jump delay after jumps, polygon delay × (1 − cos φ) with
// the laser on between marks, mark delay after a stroke — in ticks — and the laser-on/off delays
// in the delay line; the variable jump delay from the settling model.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "marker/locus/locus_generator.hpp"
#include "marker/plan/plan.hpp"
#include "marker/plan/settle_model.hpp"
#include "tests/marker/plan_test_support.hpp"

namespace mark {
namespace {

using test::figure_of;

constexpr double kDelayTau = 0.12e-3;  // 12 ticks of 10 µs

// A stroke turning 90° then 45°: (0,0) → (1,0) → (1,1) → (1 − 0.7071, 1.7071).
Figure zigzag() {
  const double s = std::sqrt(0.5);
  return figure_of({{Element::line({0, 0}, {1, 0}), Element::line({1, 0}, {1, 1}),
                     Element::line({1, 1}, {1 - s, 1 + s})}});
}

TEST(PlanDelays, DwellsInTicksFromTau) {
  Pen pen = default_pen(CornerStrategy::delays, kDelayTau, 500, 5000);
  pen.jump_settle_mm = 0;  // fixed jump delay only
  const Plan p = plan_strokes(strokes_of(zigzag()), pen, Point(-2, 0));
  const auto& c = p.commands;
  ASSERT_EQ(c.size(), 8u);
  EXPECT_EQ(c[0].kind, CommandKind::jump);
  EXPECT_EQ(c[1].kind, CommandKind::dwell);  // jump delay 2τ = 24 ticks, laser off
  EXPECT_EQ(c[1].dwell_ticks, 24u);
  EXPECT_FALSE(c[1].laser());
  EXPECT_EQ(c[2].role, CommandRole::stroke);
  EXPECT_EQ(c[3].dwell_ticks, 6u);  // polygon 0.5τ × (1 − cos 90°) = 6 ticks, laser on
  EXPECT_TRUE(c[3].laser());
  EXPECT_EQ(c[5].dwell_ticks, 2u);  // 6 × (1 − cos 45°) = 1.76 → 2 ticks
  EXPECT_TRUE(c[5].laser());
  // Mark delay τ = 12 ticks, lengthened to the laser-off delay 1.2τ = 14 ticks so no jump
  // starts with the laser on.
  EXPECT_EQ(c[7].dwell_ticks, 14u);
  EXPECT_FALSE(c[7].laser());
  EXPECT_EQ(pen.ticks(pen.laser_on_delay_s), 7u);   // 0.6τ = 7.2 ticks
  EXPECT_EQ(pen.ticks(pen.laser_off_delay_s), 14u);  // 1.2τ = 14.4 ticks

  // The locus holds the mirrors exactly that long: the dwells' samples sit on the corners.
  LocusGenerator gen(p.commands, pen.tick_s);
  std::vector<ScanSample> s(LocusGenerator::count_samples(p.commands, pen.tick_s));
  ASSERT_EQ(gen.generate(s.data(), s.size()), s.size());
  const std::size_t jump = 2000 / 50;  // 2 mm at 5 m/s: 40 ticks
  for (std::size_t i = jump; i < jump + 24; ++i) {
    EXPECT_EQ(s[i].x_mm, 0.0f);
    EXPECT_FALSE(s[i].laser);
  }
  const std::size_t corner = jump + 24 + 200;  // 1 mm at 500 mm/s: 200 ticks
  EXPECT_EQ(s[corner - 1].x_mm, 1.0f);
  for (std::size_t i = corner; i < corner + 6; ++i) {
    EXPECT_EQ(s[i].x_mm, 1.0f);
    EXPECT_EQ(s[i].y_mm, 0.0f);
    EXPECT_TRUE(s[i].laser);
  }
  EXPECT_NE(s[corner + 6].y_mm, 0.0f);
}

TEST(PlanDelays, StraightContinuationGetsNoPolygonDelay) {
  const Pen pen = default_pen(CornerStrategy::delays, kDelayTau, 500, 5000);
  const Plan p = plan_figure(
      figure_of({{Element::line({0, 0}, {1, 0}), Element::line({1, 0}, {2, 0})}}), pen);
  std::size_t lit_dwells = 0;
  for (const Command& c : p.commands) lit_dwells += c.kind == CommandKind::dwell && c.laser();
  EXPECT_EQ(lit_dwells, 0u);
}

TEST(PlanDelays, VariableJumpDelaySettlesLongJumps) {
  const Pen pen = default_pen(CornerStrategy::delays, kDelayTau, 500, 5000);
  ASSERT_GT(pen.jump_settle_mm, 0);
  auto jump_delay_ticks = [&](double jump_mm) {
    const Plan p = plan_figure(figure_of({{Element::line({jump_mm, 0}, {jump_mm + 1, 0})}}), pen);
    return p.commands.at(1).dwell_ticks;
  };
  // 2 µm: the transient is tiny, the fixed 2τ rule holds.
  EXPECT_EQ(jump_delay_ticks(0.002), 24u);
  // 2 mm at 5 m/s (0.4 ms): the lag built up is τ·v·(1 − e^(−T/τ)); it must decay to ε by the
  // time the laser comes on, 0.6τ after the delay.
  const double t = 2.0 / 5000;
  const double a = transient_mm({0, 0}, {5000, 0}, t, {0, 0}, kDelayTau);
  const double want_s = kDelayTau * std::log(a / pen.jump_settle_mm) - pen.laser_on_delay_s;
  EXPECT_EQ(jump_delay_ticks(2.0), pen.ticks(want_s));
  EXPECT_GT(jump_delay_ticks(2.0), 24u);
  EXPECT_GE(jump_delay_ticks(20.0), jump_delay_ticks(2.0));
}

}  // namespace
}  // namespace mark
