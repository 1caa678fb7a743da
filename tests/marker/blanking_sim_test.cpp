// The blanking parameters on the simulated SL10 head (first-order lag τ = 0.12 ms): a run-out of
// exactly v·τ lets the τ-delayed laser switch off on the end point; a shorter one leaves a tail;
// the settling run-in keeps the jump's transient out of the mark; corners under the blank angle
// stay lit with only a small cut.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "driver/sim/quality.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/simulate_plan.hpp"
#include "marker/plan/plan.hpp"
#include "tests/marker/plan_test_support.hpp"

namespace mark {
namespace {

struct Marked {
  Quality quality;
  double time_s;
};

// Plan → locus → laser delay line → simulated SL10, then the quality figures.
Marked simulate(const Figure& f, const Pen& pen) {
  const Plan plan = plan_figure(f, pen);
  SimScanner sim(simulator_options(head_sl10(), pen));
  simulate_plan(plan, sim);
  return {evaluate_quality(intended_polylines(f), sim.lit_paths(), sim.dose(), sim.intent()), sim.device_time_s()};
}

Pen blanking(double speed) {
  return pen_for_head(head_sl10(), CornerStrategy::blanking, speed);
}

TEST(BlankingSim, RunOutOfOneVTauStopsOnTheEndPoint) {
  // Two strokes: after the first, the jump to the second pulls the mirrors sideways.
  const Figure f = test::figure_of({{Element::line({1, 1}, {3, 1})}, {Element::line({3, 3}, {1, 3})}});
  Pen pen = blanking(1000);  // v·τ = 0.12 mm
  const Marked exact = simulate(f, pen);
  EXPECT_LT(exact.quality.overshoot_um, 0.5);
  EXPECT_LT(exact.quality.max_deviation_um, 1.5);
  EXPECT_GT(exact.quality.coverage, 0.999);
  pen.run_out_mm = 0.8 * 1000 * 0.12e-3;  // the jump pulls the beam away while still lit
  const Marked short_run_out = simulate(f, pen);
  EXPECT_GT(short_run_out.quality.max_deviation_um, 5.0);
  EXPECT_GT(short_run_out.quality.overshoot_um, 2.0);
}

TEST(BlankingSim, SettlingRunInKeepsTheJumpOutOfTheMark) {
  // A stroke 20 mm from home: the jump's lag (up to 1.15 mm at 9.6 m/s) must be gone when the
  // laser comes on.
  const Figure f = test::figure_of({{Element::line({20, 5}, {22, 5})}});
  Pen pen = blanking(500);
  const Marked settled = simulate(f, pen);
  EXPECT_LT(settled.quality.max_deviation_um, 1.5);
  pen.run_in_mm = 1 * 500 * 0.12e-3;  // a fixed run-in of v·τ
  EXPECT_GT(simulate(f, pen).quality.max_deviation_um, 50.0);
}

// A regular 24-gon of radius 1 mm (15° turns) at 500 mm/s: blanked corners (threshold 8°) keep
// the beam on the polygon (measured 0.8 µm, 30.3 ms); corners left lit (threshold 20°) are cut
// by the lag by a few µm (measured 5.8 µm) in less than half the time (13.4 ms).
TEST(BlankingSim, BlankAngleTradesCornerCutForTime) {
  std::vector<Element> sides;
  const int n = 24;
  for (int i = 0; i < n; ++i) {
    const double a0 = 2 * std::numbers::pi * i / n, a1 = 2 * std::numbers::pi * (i + 1) / n;
    sides.push_back(Element::line({std::cos(a0), std::sin(a0)}, {std::cos(a1), std::sin(a1)}));
  }
  const Figure f = test::figure_of({sides});
  Pen pen = blanking(500);
  pen.blank_angle_deg = 8;
  const Marked blanked = simulate(f, pen);
  pen.blank_angle_deg = 20;
  const Marked lit = simulate(f, pen);
  EXPECT_LT(blanked.quality.max_deviation_um, 1.5);
  EXPECT_GT(lit.quality.max_deviation_um, 4.0);
  EXPECT_LT(lit.quality.max_deviation_um, 8.0);
  EXPECT_LT(lit.time_s, 0.5 * blanked.time_s);
}

// Why blanking's "good" rows in cps stop where they do (issue 24). Blanking marks every element
// at the pen's speed, so on a tight curve the lag shrinks the circle: in steady state a
// first-order lag τ follows a circle of radius r run at v (ω = v/r) on one of radius
// r / √(1 + (ωτ)²), its gain at ω — inside the intended line. The dot of the built-in 'i' and
// 'j' is such a circle, r = 40 µm: at the good row's 298 mm/s the beam runs about 10 µm inside
// it and the dose on the intended line falls to 80 % of the pen's, the least-dosed stroke of the
// 62 characters (measured with the row's mark_args on each character alone). The beam is not
// faster than the pen there (it is slower: 0.75 v on the smaller circle); the dose is low because
// the line is in the wrong place. Checked here against the lag's own steady-state gain, which the
// simulator does not compute anywhere.
TEST(BlankingSim, ATightCircleShrinksByTheFirstOrderLagsGain) {
  const double r = 0.04, tau = head_sl10().tau_s;
  const Point c(5, 5);
  const Figure f = test::figure_of({{Element::arc(c, r, 0, 2 * std::numbers::pi)}});
  std::vector<double> dose;
  for (const double v : {100.0, 200.0, 300.0}) {
    const Pen pen = blanking(v);
    const Plan plan = plan_figure(f, pen);
    SimScanner sim(simulator_options(head_sl10(), pen));
    simulate_plan(plan, sim);
    const auto& runs = sim.lit_paths().runs;
    ASSERT_EQ(runs.size(), 1u) << v;
    // The circle takes 2πr/v ≥ 7τ: from its middle on the entry transient has decayed; the
    // last τ·v, where the beam already answers the run-out, is left out.
    const std::vector<Vec2>& run = runs.front();
    double sum = 0;
    int n = 0;
    for (std::size_t i = run.size() / 2; i < run.size() * 8 / 10; ++i, ++n)
      sum += std::hypot(run[i].x - c.x(), run[i].y - c.y());
    ASSERT_GT(n, 10) << v;
    const double beam_r = r / std::sqrt(1 + std::pow(v * tau / r, 2));
    EXPECT_NEAR(sum / n * 1e3, beam_r * 1e3, 0.3) << v << " mm/s";
    // simulate_plan runs the plan without a job header, so the pen's nominal is stated here:
    // full power at v.
    MarkIntent intent = sim.intent();
    intent.nominal_dose_s_per_mm = 1 / v;
    const Quality q = evaluate_quality(intended_polylines(f), sim.lit_paths(), sim.dose(), intent);
    EXPECT_GE(q.max_deviation_um, (r - beam_r) * 1e3 - 0.5) << v << " mm/s";
    dose.push_back(q.dose_per_mm_fraction);
  }
  // 1.7, 5.7, 10.3 µm inside: the intended line gets less and less of the pen's dose.
  EXPECT_GT(dose[0], 0.95);
  EXPECT_GT(dose[0], dose[1]);
  EXPECT_GT(dose[1], dose[2]);
  EXPECT_LT(dose[2], 0.85);
}

}  // namespace
}  // namespace mark
