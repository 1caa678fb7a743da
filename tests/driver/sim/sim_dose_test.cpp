// Dose of the simulated laser: dose = time × power, deposited along the real beam path without
// gaps, even along a constant-speed line; the laser rise time; device time = samples × tick;
// the lit path recording.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "driver/sim/sim_scanner.hpp"
#include "tests/driver/command_streams.hpp"

namespace mark {
namespace {

using test::Stream;

// Constant-speed lit line from a to b, started after a settled jump and with long run-in
// (the laser on only between a and b would still start the mirrors from rest, so the even
// stretch is checked 1 mm away from the ends).
void expect_even_line(Vec2 a, Vec2 b, double v) {
  SimScanner sim;
  Stream s;
  s.step_to(a, 300).move(b, v, true).hold(100, false);
  sim.write(s.samples());
  const Vec2 d = (1 / norm(b - a)) * (b - a);
  std::vector<double> dose;
  for (double u = 1.0; u <= norm(b - a) - 1.0; u += 0.005) {
    // Sample on the beam's own path: it lags τ·v behind but stays on the line.
    dose.push_back(sim.dose().sum_disc(a + u * d, 0.015));
  }
  const auto [lo, hi] = std::minmax_element(dose.begin(), dose.end());
  EXPECT_GT(*lo, 0.0);
  EXPECT_LT(*hi / *lo, 1.06) << "line at " << std::atan2(d.y, d.x) * 180 / M_PI << "°";
  // Every second of laser-on time at full power is in the raster.
  const double lit_s = static_cast<double>(
      std::count_if(s.samples().begin(), s.samples().end(), [](const auto& x) { return x.laser; }));
  EXPECT_NEAR(sim.dose().total(), lit_s * 10e-6, 1e-9);
}

TEST(SimDose, EvenAlongAConstantSpeedLine) {
  expect_even_line({-3, 0}, {3, 0}, 500);
  expect_even_line({-3, -1}, {2, 2}, 2000);     // oblique, 4 µm... 20 µm per tick
  expect_even_line({1, 4}, {1.5, -2}, 4000);    // fast, 40 µm per tick: sub-steps fill gaps
}

TEST(SimDose, BeamSlowingAtACornerBurnsIn) {
  // A 90° corner without any pause: the beam rounds it slower than v, so the dose near the
  // corner is higher than on the straight legs.
  SimScanner sim;
  Stream s;
  s.step_to({-3, 0}, 300).move({0, 0}, 1000, true).move({0, 3}, 1000, true).hold(50, false);
  sim.write(s.samples());
  const double straight = sim.dose().sum_disc({-1.5, 0}, 0.015);
  double corner = 0;
  for (double u = 0; u < 0.2; u += 0.005)
    corner = std::max(corner, sim.dose().sum_disc({-0.06 + u * 0.3, 0.06 - u * 0.3}, 0.015));
  EXPECT_GT(corner, 1.2 * straight);
}

TEST(SimDose, LaserRiseTimeDelaysTheDose) {
  // Dwell lit for T with a first-order rise τr: dose = T − τr·(1 − e^(−T/τr)).
  SimScannerOptions o;
  o.laser_rise_s = 50e-6;
  SimScanner sim(o);
  Stream s;
  s.hold(30, true);  // 300 µs
  sim.write(s.samples());
  const double T = 300e-6, tr = 50e-6;
  EXPECT_NEAR(sim.dose().total(), T - tr * (1 - std::exp(-T / tr)), 0.002 * T);
  EXPECT_NEAR(sim.laser_power(), 1 - std::exp(-T / tr), 1e-3);
}

TEST(SimDose, PowerScalesTheDose) {
  SimScanner sim;
  std::vector<ScanSample> half(100, ScanSample{0, 0, true, 128});
  sim.write(half);
  EXPECT_NEAR(sim.dose().total(), 100 * 10e-6 * 128.0 / 255.0, 1e-12);
}

TEST(SimDose, DeviceTimeIsSamplesTimesTick) {
  SimScannerOptions o;
  o.tick_s = 20e-6;
  SimScanner sim(o);
  Stream s(20e-6);
  s.move({1, 1}, 500, false).hold(17, false);
  sim.write(s.samples());
  EXPECT_EQ(sim.samples(), s.samples().size());
  EXPECT_DOUBLE_EQ(sim.device_time_s(), static_cast<double>(s.samples().size()) * 20e-6);
}

TEST(SimDose, LitPathsFollowTheBeamOnePolylinePerLitRun) {
  SimScanner sim;
  Stream s;
  s.step_to({-2, 0}, 200).move({0, 0}, 1000, true).hold(50, false);
  s.move({0, 1}, 5000, false).hold(200, false).move({2, 1}, 1000, true).hold(50, false);
  sim.write(s.samples());
  const LitPaths& lit = sim.lit_paths();
  ASSERT_EQ(lit.runs.size(), 2u);
  for (const auto& run : lit.runs) {
    ASSERT_GE(run.size(), 2u);
    for (std::size_t i = 1; i + 1 < run.size(); ++i)
      EXPECT_GE(norm(run[i] - run[i - 1]), sim.options().lit_path_spacing_mm - 1e-12);
  }
  // The first run starts where the beam was when the laser came on (settled at −2, 0).
  EXPECT_NEAR(lit.runs[0].front().x, -2.0, 1e-3);
  EXPECT_NEAR(lit.runs[1].front().y, 1.0, 1e-3);
}

// The lit path is relative to the commanded power: a line marked at a fifth of full power is
// lit from end to end (an absolute threshold of half power would record nothing), and a power
// that falls along the stroke (speed scaling) keeps the run in one piece.
TEST(SimDose, LowAndVaryingPowerStillCountsAsLit) {
  SimScanner sim;
  Stream s;
  s.step_to({-2, 0}, 200).move({2, 0}, 500, true).hold(50, false);
  std::vector<ScanSample> samples = s.samples();
  for (ScanSample& x : samples) x.power = 51;  // 20 %
  sim.write(samples);
  ASSERT_EQ(sim.lit_paths().runs.size(), 1u);
  EXPECT_NEAR(sim.lit_paths().runs[0].front().x, -2.0, 1e-3);
  // The laser goes off with the last command sample, the beam τ·v behind it.
  EXPECT_NEAR(sim.lit_paths().runs[0].back().x, 2.0 - 500 * head_sl10().tau_s, 1e-3);

  SimScannerOptions o;
  o.laser_rise_s = 20e-6;
  SimScanner ramp(o);
  samples = s.samples();
  int lit = 0, n = 0;
  for (ScanSample& x : samples) n += x.laser;
  for (ScanSample& x : samples)
    if (x.laser) x.power = static_cast<std::uint8_t>(255 - 250 * lit++ / n);  // 255 → 5
  ramp.write(samples);
  EXPECT_EQ(ramp.lit_paths().runs.size(), 1u);
}

// After laser-off the falling power counts as lit down to half of the last on-power, so a slow
// laser's tail is part of the mark (at full and at low pen power alike).
TEST(SimDose, FallingPowerIsLitUntilHalfOfTheLastOnPower) {
  for (std::uint8_t power : {std::uint8_t{255}, std::uint8_t{40}}) {
    SimScannerOptions o;
    o.laser_rise_s = 50e-6;
    SimScanner sim(o);
    Stream s;
    s.hold(100, true).move({1, 0}, 1000, false);  // lit dwell, then off while moving 1 m/s
    std::vector<ScanSample> samples = s.samples();
    for (ScanSample& x : samples) x.power = power;
    sim.write(samples);
    ASSERT_EQ(sim.lit_paths().runs.size(), 1u);
    // Power falls to half after τr·ln 2 ≈ 34.7 µm of travel (the command lags the beam by τ,
    // so the beam has moved a little less).
    const double end = sim.lit_paths().runs[0].back().x;
    EXPECT_GT(end, 0.0);
    EXPECT_LT(end, 1000 * 50e-6 * std::log(2.0) + 1e-3);
  }
}

}  // namespace
}  // namespace mark
