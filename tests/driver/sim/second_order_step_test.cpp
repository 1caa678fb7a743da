// The second-order servo's exact step, checked against closed forms written independently of the
// matrix exponential (critical damping's (y0 + (v0 + ωn·y0)·t)·e^{−ωn·t}, the underdamped and
// overdamped solutions), and the simulated head's step response across every ζ that
// --head-zeta accepts (0.05 to 10): it settles to the command, overshoots no more than the
// linear loop does, and stays finite where the explicit step it replaced diverged (ζ > 7.75 on
// SL10 at 1 µs).
#include "driver/sim/second_order_step.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "driver/sim/sim_scanner.hpp"
#include "tests/driver/command_streams.hpp"

namespace mark {
namespace {

// y(t) of ÿ = −ωn²y − 2ζωn·ẏ from (y0, v0), the textbook solutions for each damping.
double closed_form(double wn, double zeta, double y0, double v0, double t) {
  if (zeta == 1) return (y0 + (v0 + wn * y0) * t) * std::exp(-wn * t);
  if (zeta < 1) {
    const double wd = wn * std::sqrt(1 - zeta * zeta);
    return std::exp(-zeta * wn * t) * (y0 * std::cos(wd * t) + (v0 + zeta * wn * y0) / wd * std::sin(wd * t));
  }
  const double r = wn * std::sqrt(zeta * zeta - 1);
  const double l1 = -zeta * wn + r, l2 = -zeta * wn - r;
  // y = A·e^{l1 t} + B·e^{l2 t}, A + B = y0, l1·A + l2·B = v0
  const double a = (v0 - l2 * y0) / (l1 - l2), b = y0 - a;
  return a * std::exp(l1 * t) + b * std::exp(l2 * t);
}

TEST(SecondOrderStep, MatchesTheClosedFormsOverManySteps) {
  constexpr double kDt = 1e-6;
  for (double zeta : {0.05, 0.7, 1.0, 1.0 + 1e-9, 2.0, 7.75, 10.0, 50.0}) {
    const double wn = 2 * zeta / 0.12e-3;  // SL10's ramp lag
    const SecondOrderStep step = second_order_step(wn, zeta, kDt);
    double x = 0.01, v = -30;  // 10 µm off the target 0, moving
    for (int k = 1; k <= 2000; ++k) {
      step.apply(x, v, 0);
      if (k % 250 != 0) continue;
      const double want = closed_form(wn, zeta == 1.0 + 1e-9 ? 1.0 : zeta, 0.01, -30, k * kDt);
      EXPECT_NEAR(x, want, 1e-9 + 1e-6 * std::abs(want)) << "ζ " << zeta << " step " << k;
    }
  }
}

TEST(SecondOrderStep, FollowsAMovingTargetExactly) {
  // From rest at 0, the target c = ċ·t: about the steady ramp x = c − (2ζ/ωn)·ċ the error is the
  // free loop's from (lag·ċ, −ċ).
  constexpr double kDt = 1e-6, kRate = 2000;
  for (double zeta : {0.05, 0.7, 1.0 + 1e-9, 10.0}) {
    const double wn = 2 * zeta / 0.21e-3, lag = 2 * zeta / wn;
    const SecondOrderStep step = second_order_step(wn, zeta, kDt);
    double x = 0, v = 0;
    for (int k = 1; k <= 1000; ++k) {
      step.apply(x, v, kRate * (k - 1) * kDt, kRate);
      if (k % 100 != 0) continue;
      const double t = k * kDt;
      const double want = kRate * t - lag * kRate + closed_form(wn, zeta > 1 && zeta < 1.0001 ? 1.0 : zeta, lag * kRate, -kRate, t);
      EXPECT_NEAR(x, want, 1e-9) << "ζ " << zeta << " step " << k;
    }
  }
}

TEST(SecondOrderStep, HoldsATargetThatIsReached) {
  const SecondOrderStep step = second_order_step(1e5, 10, 1e-6);
  double x = 3, v = 0;
  step.apply(x, v, 3);
  EXPECT_DOUBLE_EQ(x, 3);
  EXPECT_DOUBLE_EQ(v, 0);
}

struct Response {
  double last = 0, peak = 0;
  bool finite = true;
};

Response step_response(double zeta, double step_mm, int hold_ticks) {
  SimScannerOptions o;
  o.head = head_sl10();
  o.head.second_order = true;
  o.head.zeta = zeta;
  o.record_lit_paths = false;
  Response r;
  o.probe = [&r](double, Vec2 p, double) {
    r.finite = r.finite && std::isfinite(p.x) && std::isfinite(p.y);
    r.peak = std::max(r.peak, p.x);
    r.last = p.x;
  };
  test::Stream s(o.tick_s);
  s.step_to({step_mm, 0}, hold_ticks);
  SimScanner sim(o);
  sim.write(s.samples());
  return r;
}

// The slowest decay rate of the loop (1/s): ζωn underdamped, the slow real pole overdamped.
double slowest_rate(double zeta, double wn) {
  return zeta < 1 ? zeta * wn : wn * (zeta - std::sqrt(zeta * zeta - 1));
}

TEST(SimScannerSecondOrder, StepSettlesToTheCommandForEveryAcceptedZeta) {
  for (double zeta : {0.05, 0.3, 0.7, 1.0, 4.0, 7.75, 8.0, 10.0}) {
    const double wn = 2 * zeta / head_sl10().tau_s;
    // Hold until the slowest mode is down to 1e-5 of the step (ln 1e5 ≈ 11.5 time constants).
    const int hold = static_cast<int>(std::ceil(11.5 / slowest_rate(zeta, wn) / 10e-6)) + 50;
    // 10 µm: the linear loop alone. It settles and overshoots no more than the linear loop's
    // e^{−πζ/√(1−ζ²)} (none from ζ = 1 on), + 0.5 %.
    const Response small = step_response(zeta, 0.01, hold);
    ASSERT_TRUE(small.finite) << "ζ " << zeta;
    EXPECT_NEAR(small.last, 0.01, 1e-6) << "ζ " << zeta;
    const double overshoot = zeta < 1 ? std::exp(-M_PI * zeta / std::sqrt(1 - zeta * zeta)) : 0;
    EXPECT_LE(small.peak, 0.01 * (1 + overshoot + 0.005)) << "ζ " << zeta;
    // 5 mm: the acceleration and speed limits first (the saturated loop overshoots by its
    // build-up of speed, about 1 mm on SL10, as it did before), then the loop; 20 ms more.
    const Response large = step_response(zeta, 5.0, hold + 2000);
    ASSERT_TRUE(large.finite) << "ζ " << zeta;
    EXPECT_NEAR(large.last, 5.0, 5e-4) << "ζ " << zeta;
    EXPECT_LE(large.peak, 5.0 * (1 + overshoot + 0.3)) << "ζ " << zeta;
  }
}

// The exact step makes the head's path independent of the sub-step (away from the limits): 10
// and 100 sub-steps per tick give the same beam on SA14 along a path with corners, so the
// simulated head is the continuous (ωn, ζ) loop, not its discretisation.
TEST(SimScannerSecondOrder, PathDoesNotDependOnTheSubStep) {
  test::Stream s;
  s.move({1, 0}, 2000, true).move({1, 1}, 2000, true).move({0, 0.5}, 1000, true).hold(50, false);
  std::vector<Vec2> path[2];
  int run = 0;
  for (int substeps : {10, 100}) {
    SimScannerOptions o;
    o.head = head_sa14();
    o.substeps = substeps;
    o.record_lit_paths = false;
    SimScanner sim(o);
    for (const ScanSample& sample : s.samples()) {
      sim.write(std::span<const ScanSample>(&sample, 1));
      path[run].push_back(sim.beam());
    }
    ++run;
  }
  double most = 0;
  for (std::size_t i = 0; i < path[0].size(); ++i) most = std::max(most, norm(path[0][i] - path[1][i]));
  EXPECT_LT(most * 1e3, 0.01);  // µm
}

}  // namespace
}  // namespace mark
