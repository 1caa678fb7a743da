// The simulated scanner against the numbers in dynamics.md §8 (first-order model): ramp lag
// τ·v within 2 %, the step settle times of the presets, the 90° corner passing 0.51·v·τ from the
// corner point with no polygon delay and 0.36·v·τ with a 0.5 τ pause (±3 %); the second-order
// model's ramp lag and overshoot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "driver/sim/sim_scanner.hpp"
#include "tests/driver/command_streams.hpp"

namespace mark {
namespace {

using test::Stream;

struct ValidationTrace {
  std::vector<double> t;
  std::vector<Vec2> p;
};

SimScanner make_sim(HeadModel head, ValidationTrace& trace, int substeps = 10) {
  SimScannerOptions o;
  o.head = std::move(head);
  o.substeps = substeps;
  o.record_lit_paths = false;
  o.probe = [&trace](double t, Vec2 p, double) {
    trace.t.push_back(t);
    trace.p.push_back(p);
  };
  return SimScanner(o);
}

// Mean lag behind the commanded ramp x = v·t, after 15 τ of settling.
void expect_ramp_lag(const HeadModel& head, double v_mm_s) {
  ValidationTrace tr;
  SimScanner sim = make_sim(head, tr);
  const double len = std::min(40.0, v_mm_s * 40 * head.tau_s);
  Stream s;
  s.move({len, 0}, v_mm_s, true);
  sim.write(s.samples());
  const double v = len / s.duration_s();  // exact command speed after rounding the step
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    if (tr.t[i] < 15 * head.tau_s) continue;
    sum += v * tr.t[i] - tr.p[i].x;
    ++n;
    ASSERT_NEAR(tr.p[i].y, 0.0, 1e-12);
  }
  ASSERT_GT(n, 100);
  const double lag = sum / n;
  EXPECT_NEAR(lag / (v * head.tau_s), 1.0, 0.02) << head.name << " at " << v << " mm/s";
}

TEST(SimValidation, RampLagIsTauTimesSpeed) {
  for (const HeadModel& h : {head_sl10(), head_sl14(), head_cheap()})
    for (double v : {200.0, 1000.0, 3000.0}) expect_ramp_lag(h, v);
}

// Last time the beam is further than `band` from `target` (settling time), from t = 0.
double settle_time(const ValidationTrace& tr, Vec2 target, double band) {
  double last = 0;
  for (std::size_t i = 0; i < tr.t.size(); ++i)
    if (norm(tr.p[i] - target) > band) last = tr.t[i];
  return last;
}

// Step settle times (to 0.1 % of the field) with the presets' conservative accelerations
// (head_model.cpp): the 1 %-of-field step is acceleration-limited now and settles a little later
// than SCANLAB's 10 mm heads (0.23–0.35 ms, 2.1–2.5 τ of their own τ), the 10 % step within or
// above the datasheet times. Windows: the simulated figure ±5 %, so a change of the physics shows.
TEST(SimValidation, StepSettleTimesWithTheConservativeAccelerations) {
  struct Case {
    HeadModel head;
    double one_percent_ms, ten_percent_ms;
  };
  for (const Case& c : {Case{head_sl10(), 0.356, 0.958}, Case{head_sl14(), 0.643, 1.776},
                        Case{head_cheap(), 0.640, 1.940},
                        Case{head_sa14(), 0.399, 1.380}}) {
    for (double share : {0.01, 0.1}) {
      ValidationTrace tr;
      SimScanner sim = make_sim(c.head, tr);
      const double step = share * c.head.field_mm;
      Stream s;
      s.step_to({step, 0}, 400);
      sim.write(s.samples());
      const double t_ms = settle_time(tr, {step, 0}, 0.001 * c.head.field_mm) * 1e3;
      const double want = share == 0.01 ? c.one_percent_ms : c.ten_percent_ms;
      EXPECT_NEAR(t_ms, want, 0.05 * want) << c.head.name << " " << share * 100 << " % step";
      // The speed limit holds throughout.
      for (std::size_t i = 1; i < tr.t.size(); ++i)
        ASSERT_LE(norm(tr.p[i] - tr.p[i - 1]) / (tr.t[i] - tr.t[i - 1]),
                  c.head.max_speed_mm_s * (1 + 1e-9));
    }
  }
}

// Closest approach of the beam to a 90° corner at the origin, approached along +x at v and
// left along +y, with `pause_ticks` of the command resting on the corner.
double corner_miss(const HeadModel& h, double v, int pause_ticks) {
  ValidationTrace tr;
  SimScanner sim = make_sim(h, tr, 20);
  Stream s;
  s.step_to({-10, 0}, 400).move({0, 0}, v, true).hold(pause_ticks, true).move({0, 10}, v, true);
  sim.write(s.samples());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < tr.t.size(); ++i)
    if (tr.t[i] > 400 * 10e-6) best = std::min(best, norm(tr.p[i]));
  return best;
}

TEST(SimValidation, NinetyDegreeCornerMissWithoutPolygonDelay) {
  const HeadModel h = head_sl10();
  for (double v : {500.0, 1000.0, 2000.0}) {
    const double vt = v * h.tau_s;
    EXPECT_NEAR(corner_miss(h, v, 0) / vt, 0.51, 0.51 * 0.03) << v << " mm/s";
  }
}

TEST(SimValidation, NinetyDegreeCornerMissWithHalfTauPause) {
  const HeadModel h = head_sl10();  // τ = 120 µs: the 0.5 τ pause is exactly 6 ticks
  for (double v : {500.0, 1000.0, 2000.0}) {
    const double vt = v * h.tau_s;
    EXPECT_NEAR(corner_miss(h, v, 6) / vt, 0.36, 0.36 * 0.03) << v << " mm/s";
  }
}

TEST(SimValidation, SecondOrderModelKeepsTheRampLagAndOvershootsByZeta) {
  HeadModel h = head_sl10();
  h.second_order = true;
  h.zeta = 0.7;
  expect_ramp_lag(h, 1000);
  // Small step (no limit active): ζ = 0.7 overshoots by exp(−πζ/√(1−ζ²)) = 4.6 %.
  ValidationTrace tr;
  SimScanner sim = make_sim(h, tr);
  Stream s;
  s.step_to({0.2, 0}, 200);
  sim.write(s.samples());
  double peak = 0;
  for (const Vec2& p : tr.p) peak = std::max(peak, p.x);
  EXPECT_NEAR((peak - 0.2) / 0.2, 0.046, 0.005);
}

}  // namespace
}  // namespace mark
