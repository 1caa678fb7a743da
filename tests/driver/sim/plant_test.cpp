// The simulated head's plant (driver/sim/plant.hpp), each effect alone against the closed form of
// what it is: a lag × tau_scale reaches 63 % of a small step at τ·scale; a dead time shifts that
// by itself; wn_scale moves a second-order step's overshoot to e^{−πζ'/√(1−ζ'²)} of the scaled ζ;
// the mirror resonance rings at its own frequency and dies by its damping and leaves a ramp
// without lag; the acceleration limit caps the jump's acceleration; 16-bit quantisation lands a
// held point on the field's code grid; noise has the rms asked for and repeats with its seed;
// back-EMF takes the acceleration away as v(t) = V·(1 − e^{−a·t/V}), and the thermal limit trips
// the drive when the rms acceleration passes it; the current loop keeps the ramp lag, overshoots a
// step the model creeps up to and changes the acceleration no faster than its slew.
#include "driver/sim/plant.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "driver/sim/sim_scanner.hpp"
#include "tests/driver/command_streams.hpp"

namespace mark {
namespace {

struct PlantTrace {
  std::vector<double> t;
  std::vector<Vec2> p;
};

PlantTrace run(const HeadModel& head, const Plant& plant, const test::Stream& stream, double tick_s = 10e-6) {
  PlantTrace tr;
  SimScannerOptions o;
  o.head = head;
  o.plant = plant;
  o.tick_s = tick_s;
  o.record_lit_paths = false;
  o.probe = [&tr](double t, Vec2 p, double) {
    tr.t.push_back(t);
    tr.p.push_back(p);
  };
  SimScanner sim(o);
  sim.write(stream.samples());
  return tr;
}

double plant_first_crossing(const PlantTrace& tr, double level) {
  for (std::size_t i = 1; i < tr.t.size(); ++i)
    if (tr.p[i].x >= level) {
      const double f = (level - tr.p[i - 1].x) / (tr.p[i].x - tr.p[i - 1].x);
      return tr.t[i - 1] + f * (tr.t[i] - tr.t[i - 1]);
    }
  return NAN;
}

// A 10 µm step commanded over one 1 µs tick (the response starts half a tick late).
double t63(const Plant& plant) {
  test::Stream s(1e-6);
  s.step_to({0.01, 0}, 2000);
  return plant_first_crossing(run(head_sl10(), plant, s, 1e-6), (1 - std::exp(-1.0)) * 0.01) - 0.5e-6;
}

TEST(Plant, DefaultIsTheModel) { EXPECT_TRUE(Plant{}.is_model()); }

TEST(Plant, TauScaleScalesTheLag) {
  const double tau = head_sl10().tau_s;
  EXPECT_NEAR(t63({}), tau, 0.01 * tau);
  for (double scale : {0.9, 1.1, 1.5}) {
    Plant p;
    p.tau_scale = scale;
    EXPECT_NEAR(t63(p), scale * tau, 0.01 * scale * tau) << scale;
  }
}

TEST(Plant, LatencyShiftsTheResponse) {
  const double tau = head_sl10().tau_s;
  for (double latency_us : {5.0, 10.0, 37.0}) {
    Plant p;
    p.latency_us = latency_us;
    EXPECT_NEAR(t63(p), tau + latency_us * 1e-6, 0.01 * tau) << latency_us;
  }
}

// A first-order loop acting on the position d old: ẋ(t) = (c − x(t − d))/τ. On a ramp at v the
// lag is v·(τ − d); nothing moves for the first d after a step.
TEST(Plant, DeadTimeShortensTheRampLagAndDelaysTheStart) {
  const double tau = head_sl10().tau_s;
  for (double dead_us : {5.0, 10.0}) {
    Plant p;
    p.dead_us = dead_us;
    test::Stream s;
    s.move({10, 0}, 1000, true);
    const PlantTrace tr = run(head_sl10(), p, s);
    const double v = 10 / s.duration_s();
    // The steady lag, after 6 ms.
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < tr.t.size(); ++i)
      if (tr.t[i] > 6e-3) sum += v * tr.t[i] - tr.p[i].x, ++n;
    EXPECT_NEAR(sum / n / v, tau - dead_us * 1e-6, 0.01 * tau) << dead_us;
  }
}

TEST(Plant, WnScaleSetsTheSecondOrderOvershoot) {
  // SA14: ζ = 0.7; ωn × w at the same lag gives ζ × w.
  for (double w : {0.5, 1.0, 1.2}) {
    Plant p;
    p.wn_scale = w;
    test::Stream s(1e-6);
    s.step_to({0.01, 0}, 4000);
    const PlantTrace tr = run(head_sa14(), p, s, 1e-6);
    double peak = 0;
    for (const Vec2& q : tr.p) peak = std::max(peak, q.x);
    const double z = 0.7 * w;
    const double overshoot = std::exp(-std::numbers::pi * z / std::sqrt(1 - z * z));
    EXPECT_NEAR(peak / 0.01 - 1, overshoot, 0.01) << w;
  }
}

TEST(Plant, ResonanceRingsAtItsFrequencyAndDiesByItsDamping) {
  Plant p;
  p.resonance_hz = 10000;
  p.resonance_zeta = 0.05;
  // A 20 µm step: the servo accelerates, the mirror twists and rings after.
  test::Stream s(1e-6);
  s.step_to({0.02, 0}, 3000);
  const PlantTrace with = run(head_sl10(), p, s, 1e-6), without = run(head_sl10(), {}, s, 1e-6);
  ASSERT_EQ(with.p.size(), without.p.size());
  // Upward zero crossings of the twist after the servo's first 0.1 ms.
  std::vector<double> ups;
  std::vector<double> peaks;
  double peak = 0;
  for (std::size_t i = 101; i < with.p.size(); ++i) {
    const double d0 = with.p[i - 1].x - without.p[i - 1].x, d1 = with.p[i].x - without.p[i].x;
    peak = std::max(peak, std::abs(d1));
    if (d0 < 0 && d1 >= 0) {
      ups.push_back(with.t[i - 1] + d0 / (d0 - d1) * (with.t[i] - with.t[i - 1]));
      peaks.push_back(peak);
      peak = 0;
    }
  }
  ASSERT_GE(ups.size(), 6u);
  const double period = (ups[5] - ups[1]) / 4;
  const double fd = 10000 * std::sqrt(1 - 0.05 * 0.05);
  EXPECT_NEAR(1 / period, fd, 0.01 * fd);
  // Amplitude per period: e^{−2πζ/√(1−ζ²)} (the servo's own response has settled by then).
  const double decay = std::exp(-2 * std::numbers::pi * 0.05 / std::sqrt(1 - 0.05 * 0.05));
  EXPECT_NEAR(peaks[5] / peaks[4], decay, 0.05 * decay);
}

TEST(Plant, ResonanceAddsNoLagOnARamp) {
  Plant p;
  p.resonance_hz = 10000;
  test::Stream s;
  s.move({10, 0}, 1000, true);
  const PlantTrace with = run(head_sl10(), p, s), without = run(head_sl10(), {}, s);
  // The start rings (ζ = 0.02 at 10 kHz dies by e over 0.8 ms); after 8 ms the ramp is steady
  // and the mirror follows the shaft with no lag of its own.
  for (std::size_t i = 0; i < with.p.size(); ++i) {
    if (with.t[i] > 8e-3) {
      ASSERT_NEAR(with.p[i].x, without.p[i].x, 1e-5) << with.t[i];
    }
  }
}

TEST(Plant, AccelerationLimitCapsAJump) {
  for (double a_max : {1e7, 3.5e7}) {
    Plant p;
    p.accel_max_mm_s2 = a_max;
    test::Stream s;
    s.step_to({20, 0}, 400);
    const PlantTrace tr = run(head_sl10(), p, s);
    double most = 0;
    for (std::size_t i = 2; i < tr.p.size(); ++i) {
      const double dt = tr.t[i] - tr.t[i - 1];
      const double a = ((tr.p[i].x - tr.p[i - 1].x) - (tr.p[i - 1].x - tr.p[i - 2].x)) / (dt * dt);
      most = std::max(most, std::abs(a));
    }
    EXPECT_NEAR(most, a_max, 1e-3 * a_max) << a_max;
    EXPECT_NEAR(tr.p.back().x, 20, 1e-3);
  }
}

// The shaft's acceleration over each sub-step, from the probe's positions (x_i − x_{i−1} = v_i·dt
// exactly when nothing displaces the beam).
std::vector<double> accelerations(const PlantTrace& tr) {
  std::vector<double> a;
  for (std::size_t i = 2; i < tr.p.size(); ++i) {
    const double dt = tr.t[i] - tr.t[i - 1];
    a.push_back(((tr.p[i].x - tr.p[i - 1].x) - (tr.p[i - 1].x - tr.p[i - 2].x)) / (dt * dt));
  }
  return a;
}

TEST(Plant, BackEmfTakesTheAccelerationAwayAsTheSpeedRises) {
  // Speeding up at the current limit against back-EMF: v̇ = a·(1 − v / V), so from rest
  // v(t) = V·(1 − e^{−a·t / V}); with a = 1e7 mm/s², V = 4000 mm/s half of V takes
  // (V / a)·ln 2 = 277.3 µs. Braking keeps the full a.
  Plant p;
  p.accel_max_mm_s2 = 1e7;
  p.backemf_speed_mm_s = 4000;
  test::Stream s;
  s.step_to({40, 0}, 2000);
  const PlantTrace tr = run(head_sl10(), p, s);
  std::size_t start = 1;
  while (start < tr.p.size() && tr.p[start].x == tr.p[start - 1].x) ++start;
  double t_half = NAN, most_braking = 0;
  for (std::size_t i = start + 1; i < tr.p.size(); ++i) {
    const double v = (tr.p[i].x - tr.p[i - 1].x) / (tr.t[i] - tr.t[i - 1]);
    if (std::isnan(t_half) && v >= 2000) t_half = tr.t[i] - tr.t[start - 1];
  }
  for (double a : accelerations(tr)) most_braking = std::min(most_braking, a);
  EXPECT_NEAR(t_half, 4000 / 1e7 * std::log(2.0), 0.02 * 277.3e-6);
  EXPECT_NEAR(most_braking, -1e7, 1e4);
  EXPECT_NEAR(tr.p.back().x, 40, 1e-3);
}

TEST(Plant, CurrentLoopKeepsTheRampLagButOvershootsAStepAndHoldsItsSlew) {
  Plant loop;
  loop.current_tau_us = 20;
  EXPECT_FALSE(loop.is_model());
  // On a steady ramp the velocity loop has nothing left to correct: the lag is v·τ as the model's.
  test::Stream ramp;
  ramp.move({10, 0}, 1000, true);
  const PlantTrace with = run(head_sl10(), loop, ramp), without = run(head_sl10(), {}, ramp);
  for (std::size_t i = 0; i < with.p.size(); ++i)
    if (with.t[i] > 4e-3 && with.t[i] < 9e-3) {
      ASSERT_NEAR(with.p[i].x, without.p[i].x, 1e-6) << with.t[i];
    }
  // A small step: the first-order model creeps up to it; through the current loop the mirror
  // overshoots (the velocity loop's lag turns the servo into a damped higher-order loop).
  const auto overshoot = [](const PlantTrace& tr) {
    double most = 0;
    for (const Vec2& p : tr.p) most = std::max(most, p.x);
    return most - 0.01;
  };
  test::Stream step(1e-6);
  step.step_to({0.01, 0}, 3000);
  EXPECT_LE(overshoot(run(head_sl10(), {}, step, 1e-6)), 1e-9);
  EXPECT_GT(overshoot(run(head_sl10(), loop, step, 1e-6)), 0.01 * 0.001);
  // A jump: the acceleration changes no faster than the slew allows; without it, faster.
  const auto jerk = [](const PlantTrace& tr) {
    const std::vector<double> a = accelerations(tr);
    double most = 0;
    for (std::size_t i = 1; i < a.size(); ++i) most = std::max(most, std::abs(a[i] - a[i - 1]) / (tr.t[i + 2] - tr.t[i + 1]));
    return most;
  };
  test::Stream jump(1e-6);
  jump.step_to({5, 0}, 3000);
  Plant slewed = loop;
  slewed.jerk_max_mm_s3 = 1e12;
  EXPECT_GT(jerk(run(head_sl10(), loop, jump, 1e-6)), 2e12);
  EXPECT_LE(jerk(run(head_sl10(), slewed, jump, 1e-6)), 1e12 * 1.001);
  const PlantTrace slewed_jump = run(head_sl10(), slewed, jump, 1e-6);
  EXPECT_NEAR(slewed_jump.p.back().x, 5, 1e-3);
}

TEST(Plant, ThermalLimitTripsTheDriveWhenTheRmsAccelerationPassesIt) {
  // A 20 mm jump accelerates at the limit from its first sub-steps: the mean square over an
  // exponential window τ_th is 1 − e^{−t/τ_th} of the peak's, so a 50 % rms limit trips at
  // t = τ_th·ln(4/3) = 287.7 µs with τ_th = 1 ms (sample 28 or 29 of 10 µs).
  Plant p;
  p.accel_max_mm_s2 = 1e7;
  p.rms_accel_pct = 50;
  p.thermal_tau_s = 1e-3;
  test::Stream s;
  s.step_to({20, 0}, 600);
  SimScannerOptions o;
  o.head = head_sl10();
  o.plant = p;
  o.record_lit_paths = false;
  SimScanner sim(o);
  try {
    sim.write(s.samples());
    FAIL() << "the drive did not trip";
  } catch (const DeviceFaultError& e) {
    EXPECT_EQ(e.fault().category, FaultCategory::device);
    EXPECT_NEAR(static_cast<double>(e.fault().at), 28.8, 1.0);
    EXPECT_NE(e.fault().message.find("x axis's rms acceleration reached 50."), std::string::npos) << e.fault().message;
    EXPECT_NE(e.fault().message.find("tripped, laser halted"), std::string::npos);
  }
  EXPECT_TRUE(sim.halted());
  EXPECT_EQ(sim.laser_power(), 0);
  // A short jump (0.1 mm: 200 µs at full acceleration) under a 1 s time constant stays far below.
  p.thermal_tau_s = 1;
  test::Stream short_jump;
  short_jump.step_to({0.1, 0}, 600);
  EXPECT_NO_THROW(run(head_sl10(), p, short_jump));
}

TEST(Plant, SixteenBitCommandsLandOnTheCodeGrid) {
  Plant p;
  p.quant_bits = 16;
  const double lsb = 110.0 / 65535;  // SL10's 110 mm field in 16-bit codes
  for (double x : {0.0123, -3.3333, 41.0}) {
    test::Stream s;
    s.step_to({x, 0}, 1000);
    const double got = run(head_sl10(), p, s).p.back().x;
    const double codes = (got + 55) / lsb;
    EXPECT_NEAR(codes, std::round(codes), 1e-4) << x;
    EXPECT_LE(std::abs(got - x), lsb / 2 + 1e-9) << x;
  }
}

TEST(Plant, NoiseHasItsRmsAndRepeatsWithItsSeed) {
  Plant p;
  p.noise_um = 1;
  test::Stream s;
  s.step_to({1, 0}, 20000);  // 200 ms at rest: about 1700 correlation times (τ = 0.12 ms)
  const PlantTrace quiet = run(head_sl10(), {}, s), a = run(head_sl10(), p, s), b = run(head_sl10(), p, s);
  p.seed = 2;
  const PlantTrace c = run(head_sl10(), p, s);
  double sum = 0, differs = 0;
  int n = 0;
  for (std::size_t i = 0; i < a.p.size(); ++i) {
    ASSERT_EQ(a.p[i].x, b.p[i].x);
    ASSERT_EQ(a.p[i].y, b.p[i].y);
    differs = std::max(differs, std::abs(a.p[i].x - c.p[i].x));
    if (a.t[i] < 10e-3) continue;
    const double dx = a.p[i].x - quiet.p[i].x, dy = a.p[i].y - quiet.p[i].y;
    sum += dx * dx + dy * dy;
    n += 2;
  }
  EXPECT_NEAR(std::sqrt(sum / n) * 1e3, 1.0, 0.08);
  EXPECT_GT(differs, 0.5e-3);
}

}  // namespace
}  // namespace mark
