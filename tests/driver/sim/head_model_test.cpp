// Head presets, measured on the simulated scanner rather than read back: a small step reaches
// 63 % (1 − 1/e) of its height one tracking error τ after it is commanded, with the τ of
// dynamics.md §8 (SL10 0.12 ms, SL14 0.21 ms, cheap 0.25 ms); a long jump runs at the preset's
// positioning speed (SCANLAB's optical angular speed × f = 160 mm) and no faster; lookup by name.
#include "driver/sim/head_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "driver/sim/sim_scanner.hpp"
#include "tests/driver/command_streams.hpp"

namespace mark {
namespace {

struct Trace {
  std::vector<double> t;
  std::vector<double> x;
};

// The beam's x after a command stream, sampled at every sub-step of a 1 µs tick.
Trace run(const HeadModel& head, const test::Stream& stream, double tick_s) {
  Trace tr;
  SimScannerOptions o;
  o.head = head;
  o.tick_s = tick_s;
  o.record_lit_paths = false;
  o.probe = [&tr](double t, Vec2 p, double) {
    tr.t.push_back(t);
    tr.x.push_back(p.x);
  };
  SimScanner sim(o);
  sim.write(stream.samples());
  return tr;
}

// First time the trace reaches `level`, interpolated between sub-steps.
double first_crossing(const Trace& tr, double level) {
  for (std::size_t i = 1; i < tr.t.size(); ++i)
    if (tr.x[i] >= level) {
      const double f = (level - tr.x[i - 1]) / (tr.x[i] - tr.x[i - 1]);
      return tr.t[i - 1] + f * (tr.t[i] - tr.t[i - 1]);
    }
  return NAN;
}

struct Reference {
  HeadModel head;
  double tau_s;          // dynamics.md §8
  double speed_rad_s;    // positioning speed, optical
};

std::vector<Reference> references() {
  return {{head_sl10(), 0.12e-3, 120}, {head_sl14(), 0.21e-3, 100}, {head_cheap(), 0.25e-3, 50}};
}

TEST(HeadModel, SmallStepReaches63PercentAfterTau) {
  constexpr double kTick = 1e-6;
  for (const Reference& r : references()) {
    // 10 µm: far below the speed and acceleration limits, so the pure lag shows.
    const double step = 0.01;
    test::Stream s(kTick);
    s.step_to({step, 0}, static_cast<int>(10 * r.tau_s / kTick));
    const Trace tr = run(r.head, s, kTick);
    // The step is commanded as a ramp over its first tick: the response starts half a tick late.
    const double t63 = first_crossing(tr, (1 - std::exp(-1.0)) * step) - kTick / 2;
    EXPECT_NEAR(t63, r.tau_s, 0.01 * r.tau_s) << r.head.name;
    // And settles: 5 τ later it is within 1 % of the step.
    EXPECT_NEAR(tr.x.back(), step, 0.01 * step) << r.head.name;
  }
}

TEST(HeadModel, LongJumpRunsAtThePositioningSpeed) {
  constexpr double kTick = 10e-6, kFocalMm = 160;
  for (const Reference& r : references()) {
    test::Stream s(kTick);
    s.step_to({50, 0}, 1000);
    const Trace tr = run(r.head, s, kTick);
    double fastest = 0;
    for (std::size_t i = 1; i < tr.t.size(); ++i)
      fastest = std::max(fastest, (tr.x[i] - tr.x[i - 1]) / (tr.t[i] - tr.t[i - 1]));
    EXPECT_NEAR(fastest, r.speed_rad_s * kFocalMm, 1e-6 * r.speed_rad_s * kFocalMm) << r.head.name;
    EXPECT_NEAR(tr.x.back(), 50, 1e-3) << r.head.name;
  }
}

TEST(HeadModel, EveryPresetFollowsTheDefaultTick) {
  // SCANLAB's rule: a command period of at most 20 % of τ; the default tick is 10 µs.
  for (const std::string& name : head_names()) {
    const HeadModel h = *find_head(name);
    EXPECT_GE(h.max_tick_s(), 10e-6) << name;
    EXPECT_NEAR(h.max_tick_s(), 0.2 * h.tau_s, 1e-15) << name;
  }
}

TEST(HeadModel, AccelerationsComeFromPublishedFiguresOrStepTimeBounds) {
  // excelliSCAN 14: 320 000 rad/s² and 200 rad/s optical at f = 160 mm.
  EXPECT_DOUBLE_EQ(head_sa14().max_accel_mm_s2, 320000 * 160.0);
  EXPECT_DOUBLE_EQ(head_sa14().max_speed_mm_s, 200 * 160.0);
  EXPECT_TRUE(head_sa14().second_order);
  // The others: at most the bang-bang bound 4·d/T² of a datasheet step (11 mm in T).
  EXPECT_LE(head_sl10().max_accel_mm_s2, 4 * 11 / (1.0e-3 * 1.0e-3) + 1);   // basiCube 10
  EXPECT_LE(head_sl14().max_accel_mm_s2, 4 * 11 / (1.9e-3 * 1.9e-3) + 1);   // intelliSCAN 20
  EXPECT_LE(head_cheap().max_accel_mm_s2, 4 * 11 / (1.2e-3 * 1.2e-3) + 1);  // SCANcube 10
}

TEST(HeadModel, SecondOrderNaturalFrequencyKeepsTheRampLag) {
  HeadModel h = head_sl14();
  h.zeta = 0.7;
  EXPECT_DOUBLE_EQ(2 * h.zeta / h.omega_n(), h.tau_s);
}

TEST(HeadModel, FoundByNameIgnoringCase) {
  ASSERT_TRUE(find_head("sl10").has_value());
  EXPECT_EQ(find_head("SL14")->name, "SL14");
  EXPECT_EQ(find_head("Cheap")->name, "cheap");
  EXPECT_FALSE(find_head("SL99").has_value());
  EXPECT_EQ(find_head("sa14")->name, "SA14");
  EXPECT_EQ(head_names().size(), 4u);
  for (const std::string& n : head_names()) EXPECT_EQ(find_head(n)->name, n);
}

}  // namespace
}  // namespace mark
