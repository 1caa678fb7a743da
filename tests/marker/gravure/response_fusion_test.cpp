// The head response from the sensing coil's position and velocity (US 6,007,230 FIG. 13–14):
// the velocity over jω is the position response; each tone fuses the two by inverse variance,
// so the position carries the low tones and the velocity the high ones; and the fit from the
// fused response finds the resonances better than the position alone when the position is noisy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/error.hpp"
#include "driver/sim/sim_stylus_head.hpp"
#include "marker/gravure/auto_tune.hpp"
#include "marker/gravure/stylus_head_response.hpp"

namespace mark {
namespace {

// The sweep played straight into a head (no drain): what the sensing coil recorded.
struct Sensed {
  std::vector<float> position_um, velocity_um_s;
};

Sensed play(const SweepPattern& pattern, SimStylusHeadOptions o) {
  o.record_profile = false;
  o.record_sense = true;
  SimStylusHead head(o);
  JobHeader header;
  header.name = "sweep";
  header.expected_samples = pattern.total_samples();
  head.begin_job(header);
  SweepPattern p = pattern;
  std::vector<double> drive(pattern.total_samples());
  p.next(drive);
  std::vector<StylusSample> samples;
  for (double d : drive) samples.push_back({static_cast<float>(d), false});
  head.write(samples);
  head.end_job();
  return {head.sensed_position_um(), head.sensed_velocity_um_s()};
}

TEST(ResponseFusion, VelocityOverJOmegaIsThePositionResponse) {
  // Noise-free: each estimate against what the held head shows there (point_response), and the
  // velocity's against the position response, which it misses by the drive's folded images.
  SimStylusHeadOptions o;
  o.sense_noise_um = 0;
  o.sense_velocity_noise_um_s = 0;
  const SweepPattern pattern(SweepOptions{});
  const Sensed s = play(pattern, o);
  const auto pos = pattern.measure(s.position_um);
  const auto vel = pattern.measure_velocity(s.velocity_um_s);
  ASSERT_EQ(pos.size(), vel.size());
  double pos_worst = 0, vel_worst = 0, bias_worst = 0, bias_10k = 0;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    EXPECT_EQ(vel[i].velocity_weight, 1);
    EXPECT_EQ(pos[i].velocity_weight, 0);
    const std::complex<double> h = held_response(o.head, pos[i].freq_hz);
    pos_worst = std::max(pos_worst, std::abs(pos[i].gain - point_response(o.head, pos[i])) / std::abs(h));
    vel_worst = std::max(vel_worst, std::abs(vel[i].gain - point_response(o.head, vel[i])) / std::abs(h));
    const double bias = std::abs(vel[i].gain - h) / std::abs(h);
    bias_worst = std::max(bias_worst, bias);
    if (vel[i].freq_hz <= 10000) bias_10k = std::max(bias_10k, bias);
  }
  std::printf("noise-free: position %.1e, velocity/jw %.1e from the held head; velocity/jw vs position "
              "response %.2f %% to 10 kHz, %.2f %% to 16 kHz\n",
              pos_worst, vel_worst, 100 * bias_10k, 100 * bias_worst);
  EXPECT_LT(pos_worst, 1e-4);
  EXPECT_LT(vel_worst, 1e-4);
  EXPECT_NEAR(bias_10k, 0.013, 0.002);
  EXPECT_NEAR(bias_worst, 0.020, 0.002);
}

TEST(ResponseFusion, EachToneTakesTheLessNoisySignal) {
  // The defaults: 0.02 µm on the position, 200 µm/s on the velocity, equal at 1.6 kHz.
  const SweepPattern pattern(SweepOptions{});
  const Sensed s = play(pattern, SimStylusHeadOptions{});
  const auto pos = pattern.measure(s.position_um);
  const auto vel = pattern.measure_velocity(s.velocity_um_s);
  const auto both = pattern.measure(s.position_um, s.velocity_um_s);
  ASSERT_EQ(both.size(), pos.size());
  double crossover_hz = 0;
  for (std::size_t i = 0; i < both.size(); ++i) {
    // Never worse than the better of the two.
    EXPECT_LE(both[i].sigma, std::min(pos[i].sigma, vel[i].sigma) * (1 + 1e-12));
    EXPECT_NEAR(both[i].velocity_weight, pos[i].sigma * pos[i].sigma /
                                             (pos[i].sigma * pos[i].sigma + vel[i].sigma * vel[i].sigma), 1e-12);
    if (crossover_hz == 0 && both[i].velocity_weight > 0.5) crossover_hz = both[i].freq_hz;
  }
  EXPECT_LT(both.front().velocity_weight, 0.1);  // 200 Hz: the position
  EXPECT_GT(both.back().velocity_weight, 0.9);   // 16 kHz: the velocity
  // The noises are equal, as a position, at 200 / 0.02 rad/s = 1.59 kHz.
  EXPECT_NEAR(crossover_hz, 1592, 1592 * 0.15) << crossover_hz;
}

TEST(ResponseFusion, TwoSweepsDoNotFuse) {
  const SweepPattern a(SweepOptions{}), b(SweepOptions{200, 16000, 40});
  const Sensed s = play(a, SimStylusHeadOptions{});
  EXPECT_THROW(fuse(a.measure(s.position_um), b.measure_velocity(s.velocity_um_s)), InputError);
  std::vector<float> shorter(s.velocity_um_s.begin(), s.velocity_um_s.end() - 1);
  EXPECT_THROW(a.measure_velocity(shorter), InputError);
}

// The worst relative error of the fitted frequencies and dampings.
struct FitError {
  double freq = 0, damping = 0;
};

FitError fit_error(const StylusHeadModel& truth, const StylusHeadModel& fit) {
  FitError e;
  if (fit.modes.size() != truth.modes.size()) return {1, 1};
  for (std::size_t i = 0; i < truth.modes.size(); ++i) {
    e.freq = std::max(e.freq, std::abs(fit.modes[i].freq_hz / truth.modes[i].freq_hz - 1));
    e.damping = std::max(e.damping, std::abs(fit.modes[i].damping / truth.modes[i].damping - 1));
  }
  return e;
}

TEST(AutoTune, FusedFitBeatsPositionOnlyOnANoisyPositionCoil) {
  // 0.5 µm rms on the position (25× the default), the velocity at its default 200 µm/s: five
  // noise seeds, the worst fitted frequency and damping error of each source.
  const ResponseSource sources[] = {ResponseSource::position, ResponseSource::velocity, ResponseSource::fused};
  FitError worst[3];
  double worst_flat[3] = {0, 0, 0};
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    for (int k = 0; k < 3; ++k) {
      SimStylusHeadOptions o;
      o.sense_noise_um = 0.5;
      o.noise_seed = seed;
      SimStylusHead head(o);
      AutoTuneOptions t;
      t.source = sources[k];
      const AutoTuneResult r = auto_tune(head, t);
      const FitError e = fit_error(o.head, r.fit.model);
      worst[k].freq = std::max(worst[k].freq, e.freq);
      worst[k].damping = std::max(worst[k].damping, e.damping);
      worst_flat[k] = std::max({worst_flat[k], r.flatness.max_db, -r.flatness.min_db});
    }
  }
  for (int k = 0; k < 3; ++k)
    std::printf("%-8s worst over 5 seeds: frequency %.3f %%, damping %.2f %%, tuned flatness ±%.2f dB\n",
                std::string(to_string(sources[k])).c_str(), 100 * worst[k].freq, 100 * worst[k].damping,
                worst_flat[k]);
  // Measured: position 0.030 % and 1.33 %, fused 0.003 % and 0.11 %, flatness ±0.58 / ±0.28 dB.
  EXPECT_LT(worst[2].freq, 0.0001);
  EXPECT_LT(worst[2].damping, 0.005);
  EXPECT_GT(worst[0].freq, 0.0002);
  EXPECT_GT(worst[0].damping, 0.01);
  EXPECT_LT(worst[2].freq * 5, worst[0].freq);
  EXPECT_LT(worst[2].damping * 5, worst[0].damping);
  EXPECT_LT(worst_flat[2], 0.4);
  EXPECT_LT(worst_flat[2], worst_flat[0]);
  // The velocity alone does as well here: the position is the worse signal at every tone.
  EXPECT_LT(worst[1].freq, 0.0001);
  EXPECT_LT(worst[1].damping, 0.005);
}

TEST(AutoTune, TheVelocityFindsTheModeThePositionNoiseBuried) {
  // head_tuning_test's TooMuchNoiseIsReportedNotHidden: at 2 µm on the position the weak 5.2 kHz
  // mode is lost from the position alone; with the velocity (default noise) it is found and the
  // head tunes flat (measured −0.30 .. 0.00 dB).
  const StylusHeadModel truth{{{2100, 0.05, 0.85}, {5200, 0.06, 0.15}}};
  SimStylusHeadOptions o;
  o.head = truth;
  o.sense_noise_um = 2;
  SimStylusHead head(o);
  const AutoTuneResult r = auto_tune(head);
  ASSERT_EQ(r.fit.model.modes.size(), 2u) << describe(r.fit.model);
  const FitError e = fit_error(truth, r.fit.model);
  EXPECT_LT(e.freq, 0.002);
  EXPECT_LT(e.damping, 0.05);
  EXPECT_TRUE(r.within_tolerance) << r.flatness.min_db << " .. " << r.flatness.max_db;
}

TEST(AutoTune, PositionOnlyAndVelocityOnlyStillTune) {
  // Default noises: either signal alone recovers the typical head and tunes it flat.
  for (const ResponseSource source : {ResponseSource::position, ResponseSource::velocity}) {
    SimStylusHead head;
    AutoTuneOptions t;
    t.source = source;
    const AutoTuneResult r = auto_tune(head, t);
    const FitError e = fit_error(default_stylus_head(), r.fit.model);
    EXPECT_LT(e.freq, 0.002) << to_string(source);
    EXPECT_LT(e.damping, 0.05) << to_string(source);
    EXPECT_TRUE(r.within_tolerance) << to_string(source) << " " << r.flatness.min_db << " .. " << r.flatness.max_db;
    for (const ResponsePoint& p : r.raw_response) EXPECT_EQ(p.velocity_weight, source == ResponseSource::velocity);
  }
}

}  // namespace
}  // namespace mark
