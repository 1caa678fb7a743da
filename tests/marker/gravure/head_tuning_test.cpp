// Filters designed for a head and the automatic tuning of FIG. 7–8: the design flattens the head
// to ±1 dB up to 10 kHz (and keeps more than 50 % amplitude at 10 kHz, the seed's requirement
// for double-frequency cells); the head response test through the line memory and drain, the
// fit recovering the simulated head's resonances within 2 % in frequency, and the measured
// response after tuning flat within ±1 dB.
#include <gtest/gtest.h>

#include <cmath>

#include "base/error.hpp"
#include "driver/sim/sim_stylus_head.hpp"
#include "marker/gravure/auto_tune.hpp"
#include "marker/gravure/biquad_cascade.hpp"
#include "marker/gravure/head_design.hpp"
#include "marker/gravure/stylus_head_fit.hpp"

namespace mark {
namespace {

const StylusHeadModel kHeads[] = {
    default_stylus_head(),
    {{{1650, 0.08, 0.75}, {6100, 0.03, 0.25}}},
    {{{2100, 0.05, 0.85}, {5200, 0.06, 0.15}}},
    {{{1900, 0.10, 0.7}, {4800, 0.05, 0.2}, {8200, 0.04, 0.1}}},
};

TEST(HeadDesign, AntiresonanceOfTheTypicalHead) {
  const std::vector<ZeroPair> z = antiresonances(default_stylus_head());
  ASSERT_EQ(z.size(), 1u);
  EXPECT_NEAR(z[0].freq_hz, 3368, 2);
  // The head's response has its dip there.
  double lowest = 1e9, at = 0;
  for (double f = 2000; f < 5000; f += 1) {
    const double g = std::abs(held_response(default_stylus_head(), f));
    if (g < lowest) lowest = g, at = f;
  }
  EXPECT_NEAR(at, z[0].freq_hz, 15);
}

TEST(HeadDesign, FiltersTimesHeadIsFlatTo10kHz) {
  for (const StylusHeadModel& head : kHeads) {
    const FilterBank bank = design_for_head(head);
    EXPECT_EQ(bank.sections.size(), 2 * head.modes.size());
    const Flatness fl = predicted_flatness(bank, head);
    EXPECT_GT(fl.min_db, -0.5) << describe(head);
    EXPECT_LT(fl.max_db, 0.5) << describe(head);
    // The head alone is nowhere near: its first resonance peaks > 10 dB.
    EXPECT_GT(predicted_flatness(FilterBank{}, head).max_db, 10) << describe(head);
    const double at10k = std::abs(response(bank, 10000) * held_response(head, 10000)) /
                         std::abs(response(bank, 1) * held_response(head, 1));
    EXPECT_GT(at10k, 0.5);
  }
}

TEST(HeadDesign, LatencyIsTheDelayOfASlowRamp) {
  // Drive a slow ramp through filters and head: the head's position follows it `latency`
  // samples late.
  const StylusHeadModel head = kHeads[1];
  const FilterBank bank = design_for_head(head);
  const double latency = latency_samples(bank, head);
  SimStylusHeadOptions o;
  o.head = head;
  o.record_profile = false;
  o.record_sense = true;
  o.sense_noise_um = 0;
  SimStylusHead sim(o);
  JobHeader header;
  header.expected_samples = 40000;
  sim.begin_job(header);
  BiquadCascade filters(bank);
  std::vector<double> drive(40000);
  for (std::size_t n = 0; n < drive.size(); ++n) drive[n] = -20 + 0.001 * static_cast<double>(n);
  filters.settle(drive[0]);
  filters.process(drive);
  std::vector<StylusSample> samples;
  for (double d : drive) samples.push_back({static_cast<float>(d), false});
  sim.write(samples);
  sim.end_job();
  const double y = sim.sensed_position_um()[30000];
  const double ramp_at = -20 + 0.001 * 30000;
  EXPECT_NEAR((ramp_at - y) / 0.001, latency, 0.05);
}

TEST(AutoTune, RecoversTheResonancesWithinTwoPercent) {
  for (const StylusHeadModel& truth : kHeads) {
    SimStylusHeadOptions o;
    o.head = truth;
    SimStylusHead head(o);
    const AutoTuneResult r = auto_tune(head);
    ASSERT_FALSE(r.cancelled);
    ASSERT_EQ(r.fit.model.modes.size(), truth.modes.size()) << describe(truth) << " fitted " << describe(r.fit.model);
    for (std::size_t i = 0; i < truth.modes.size(); ++i) {
      const StylusMode& t = truth.modes[i];
      const StylusMode& f = r.fit.model.modes[i];
      EXPECT_NEAR(f.freq_hz / t.freq_hz, 1, 0.02) << describe(truth);
      EXPECT_NEAR(f.freq_hz / t.freq_hz, 1, 0.002) << describe(truth);  // in fact far closer
      EXPECT_NEAR(f.damping / t.damping, 1, 0.05) << describe(truth);
      EXPECT_NEAR(f.gain / t.gain, 1, 0.05) << describe(truth);
    }
    EXPECT_TRUE(r.within_tolerance) << r.flatness.min_db << " .. " << r.flatness.max_db;
    EXPECT_GT(r.flatness.min_db, -1);
    EXPECT_LT(r.flatness.max_db, 1);
    // Before tuning the same test shows the resonance peaks.
    EXPECT_GT(measured_flatness(r.raw_response).max_db, 10);
    EXPECT_GT(r.test_time_s, 2);  // two sweeps of device time
    EXPECT_EQ(head.status().state, DeviceState::idle);
  }
}

TEST(AutoTune, ANoisySensingCoilStillGivesTheResonances) {
  // 0.5 µm rms of coil noise against the test's 1 µm drive: the gains above 10 kHz are buried in
  // it, the fit weights them by their uncertainty and still lands within 2 %. From the position
  // alone (with the velocity, response_fusion_test.cpp, it does far better).
  for (const StylusHeadModel& truth : {kHeads[0], kHeads[3]}) {
    SimStylusHeadOptions o;
    o.head = truth;
    o.sense_noise_um = 0.5;
    SimStylusHead head(o);
    AutoTuneOptions position_only;
    position_only.source = ResponseSource::position;
    const AutoTuneResult r = auto_tune(head, position_only);
    ASSERT_EQ(r.fit.model.modes.size(), truth.modes.size()) << describe(r.fit.model);
    for (std::size_t i = 0; i < truth.modes.size(); ++i)
      EXPECT_NEAR(r.fit.model.modes[i].freq_hz / truth.modes[i].freq_hz, 1, 0.02) << describe(r.fit.model);
    EXPECT_TRUE(r.within_tolerance) << r.flatness.min_db << " .. " << r.flatness.max_db;
  }
}

TEST(AutoTune, TooMuchNoiseIsReportedNotHidden) {
  // At 2 µm of noise the weak 5.2 kHz mode of this head is lost: the verification sweep shows
  // it and the result says the tuning is not within ±1 dB. (Tuned from the position alone: the
  // velocity, at its default noise, would find the mode.)
  SimStylusHeadOptions o;
  o.head = kHeads[2];
  o.sense_noise_um = 2;
  SimStylusHead head(o);
  AutoTuneOptions position_only;
  position_only.source = ResponseSource::position;
  const AutoTuneResult r = auto_tune(head, position_only);
  EXPECT_FALSE(r.within_tolerance);
  EXPECT_GT(r.flatness.max_db - r.flatness.min_db, 2);
}

TEST(AutoTune, NominalFiltersOnADriftedHeadAreNotFlatTunedOnesAre) {
  const StylusHeadModel drifted{{{1700, 0.07, 0.8}, {5800, 0.035, 0.2}}};
  const Flatness nominal = predicted_flatness(design_for_head(default_stylus_head()), drifted);
  EXPECT_TRUE(nominal.max_db > 1 || nominal.min_db < -1);
  SimStylusHeadOptions o;
  o.head = drifted;
  SimStylusHead head(o);
  const AutoTuneResult r = auto_tune(head);
  EXPECT_TRUE(r.within_tolerance);
}

TEST(HeadFit, AFlatResponseHasNoResonanceToFit) {
  std::vector<ResponsePoint> flat;
  for (double f = 100; f < 20000; f *= 1.1) flat.push_back({f, {1, 0}});
  EXPECT_THROW(fit_head(flat), InputError);
}

TEST(AutoTune, CancelStopsTheTestWithTheStylusLifted) {
  SimStylusHead head;
  AutoTuneOptions o;
  o.run.stop_at = 5000;
  const AutoTuneResult r = auto_tune(head, o);
  EXPECT_TRUE(r.cancelled);
  EXPECT_TRUE(head.lifted());
}

}  // namespace
}  // namespace mark
