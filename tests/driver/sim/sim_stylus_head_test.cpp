// The simulated stylus head: its motion is the exact held response of the modal model (checked
// against the closed-form step response and against held_response for sines), the diamond cuts
// only below the surface, the sensing coil reports position and velocity, the cells are
// measured as the samples arrive, and the safety rules hold — a lifted sample, halt() or abort()
// retracts the head for the rest of the job, a drive outside the amplifier's range is refused.
#include "driver/sim/sim_stylus_head.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mark {
namespace {

JobHeader job(std::uint64_t samples) {
  JobHeader h;
  h.name = "test";
  h.expected_samples = samples;
  return h;
}

std::vector<StylusSample> constant(std::size_t n, float drive) {
  return std::vector<StylusSample>(n, StylusSample{drive, false});
}

SimStylusHeadOptions quiet(StylusHeadModel head = default_stylus_head()) {
  SimStylusHeadOptions o;
  o.head = head;
  o.sense_noise_um = 0;
  o.sense_velocity_noise_um_s = 0;
  o.record_sense = true;
  return o;
}

TEST(SimStylusHead, StepResponseIsTheModalSum) {
  SimStylusHead head(quiet());
  head.begin_job(job(4001));
  head.write(constant(1, -10));  // settles at −10 µm
  head.write(constant(4000, 30));
  head.end_job();
  const auto& y = head.sensed_position_um();
  ASSERT_EQ(y.size(), 4001u);
  EXPECT_NEAR(y[0], -10, 1e-6);
  for (std::size_t k = 1; k <= 4000; k += 37) {
    const double t = k * kStylusTick_s;  // the step acts from the start of tick 1
    double expected = 0;
    for (const StylusMode& m : default_stylus_head().modes) {
      const double w = 2 * std::numbers::pi * m.freq_hz, s = m.damping * w, wd = w * std::sqrt(1 - m.damping * m.damping);
      expected += m.gain * (-10 + 40 * (1 - std::exp(-s * t) * (std::cos(wd * t) + s / wd * std::sin(wd * t))));
    }
    EXPECT_NEAR(y[k], expected, 1e-4) << k;
  }
}

TEST(SimStylusHead, SineResponseIsTheHeldResponse) {
  for (double f : {500.0, 1800.0, 3368.0, 5500.0, 9000.0}) {
    SimStylusHead head(quiet());
    const std::size_t n = 200000;
    head.begin_job(job(n));
    std::vector<StylusSample> s(n);
    const double w = 2 * std::numbers::pi * f * kStylusTick_s;
    for (std::size_t k = 0; k < n; ++k) s[k] = {static_cast<float>(-30 + std::sin(w * k)), false};
    head.write(s);
    head.end_job();
    // Correlate the last 100000 samples (ringing died away) with e^{-jωk}.
    std::complex<double> y = 0, u = 0;
    for (std::size_t k = 100000; k < n; ++k) {
      const std::complex<double> e = std::polar(1.0, -w * k);
      y += (head.sensed_position_um()[k] + 30.0) * e;
      u += std::sin(w * k) * e;
    }
    const std::complex<double> h = held_response(default_stylus_head(), f);
    EXPECT_NEAR(std::abs(y / u) / std::abs(h), 1, 2e-3) << f;
    EXPECT_NEAR(std::arg((y / u) / h), 0, 2e-3) << f;
  }
}

TEST(SimStylusHead, CutsOnlyBelowTheSurfaceAndMeasuresCells) {
  SimStylusHeadOptions o = quiet();
  o.cells = CellGeometry{6250, 140, 120};
  SimStylusHead head(o);
  head.begin_job(job(320));
  head.write(constant(320, -5));  // held above the surface: no cut at all
  const DeviceReport r = head.end_job();
  EXPECT_EQ(r.outcome, DeviceState::done);
  EXPECT_EQ(r.samples_out, 320u);
  EXPECT_NEAR(r.device_time_s, 320 * 5e-6, 1e-12);
  for (float c : head.cut_profile_um()) EXPECT_EQ(c, 0.0f);
  ASSERT_EQ(head.cells().size(), 10u);
  for (const CellFigures& c : head.cells()) EXPECT_EQ(c.volume_um3, 0.0f);

  head.reset();
  head.begin_job(job(320));
  head.write(constant(320, 12));  // settled 12 µm deep: every cell cut 12 µm deep all along
  head.end_job();
  for (float c : head.cut_profile_um()) EXPECT_NEAR(c, 12, 1e-4);
  const CellFigures& c = head.cells()[3];
  EXPECT_NEAR(c.depth_um, 12, 1e-4);
  EXPECT_NEAR(c.length_um, 140, 1e-3);
  const double half_width = std::tan(std::numbers::pi / 3);
  EXPECT_NEAR(c.area_um2, 2 * half_width * 12 * 140, 0.1);
  EXPECT_NEAR(c.volume_um3, half_width * 144 * 140, 1);
}

TEST(CellMeter, LengthsResolveBelowOneSample) {
  // A triangle cut: 0 at sample 4, 8 µm at sample 8, 0 at sample 12 (linear in between): the cut
  // spans exactly 8 sample pitches.
  std::vector<float> cut(32, -2.0f);
  for (int k = 4; k <= 12; ++k) cut[k] = 8 - 2.0f * std::abs(k - 8);
  cut[3] = -2;
  cut[13] = -2;
  const CellGeometry g{6250, 32, 120};  // 1 µm a sample
  const std::vector<CellFigures> cells = measure_cells(cut, g);
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_NEAR(cells[0].length_um, 8, 1e-6);
  EXPECT_NEAR(cells[0].depth_um, 8, 1e-6);
  // Crossings between samples: the cut runs from 4.75 to 11.25.
  for (int k = 0; k < 32; ++k) cut[k] = 6.5f - 2.0f * std::abs(k - 8.0f);
  EXPECT_NEAR(measure_cells(cut, g)[0].length_um, 6.5, 1e-6);
}

TEST(SimStylusHead, ALiftedSampleRetractsTheHeadForTheRestOfTheJob) {
  SimStylusHead head(quiet());
  head.begin_job(job(300));
  head.write(constant(100, 20));
  EXPECT_TRUE(head.status().laser_on);  // cutting
  head.write(std::vector<StylusSample>(1, safe_sample(StylusSample{20, false})));
  head.write(constant(199, 20));  // the job goes on asking for 20 µm: nothing is cut
  head.end_job();
  const auto& cut = head.cut_profile_um();
  ASSERT_EQ(cut.size(), 300u);
  EXPECT_GT(cut[99], 19);
  for (std::size_t k = 100; k < 300; ++k) EXPECT_EQ(cut[k], 0.0f) << k;
  EXPECT_TRUE(head.lifted());
  EXPECT_FALSE(head.status().laser_on);
}

TEST(SimStylusHead, SafeSampleIsNeverTheLastDepth) {
  const StylusSample s = safe_sample(StylusSample{35, false});
  EXPECT_TRUE(s.lifted);
  EXPECT_LT(s.drive_um, 0);
}

TEST(SimStylusHead, HaltAndAbortRetract) {
  SimStylusHead head(quiet());
  head.begin_job(job(100));
  head.write(constant(50, 20));
  head.halt();
  EXPECT_TRUE(head.lifted());
  EXPECT_THROW(head.write(constant(10, 20)), DeviceError);
  EXPECT_EQ(head.end_job().samples_out, 50u);
  head.reset();

  head.begin_job(job(100));
  head.write(constant(50, 20));
  head.abort();
  EXPECT_EQ(head.status().state, DeviceState::aborted);
  EXPECT_THROW(head.write(constant(10, 20)), DeviceError);
  EXPECT_EQ(head.end_job().outcome, DeviceState::aborted);
  head.reset();
  EXPECT_EQ(head.status().state, DeviceState::idle);
}

TEST(SimStylusHead, RefusesADriveOutsideTheAmplifierRange) {
  SimStylusHead head(quiet());
  head.begin_job(job(100));
  head.write(constant(10, 20));
  std::vector<StylusSample> bad = constant(10, 20);
  bad[4].drive_um = 1500;
  try {
    head.write(bad);
    FAIL();
  } catch (const DeviceFaultError& e) {
    EXPECT_EQ(e.fault().category, FaultCategory::out_of_field);
    EXPECT_EQ(e.fault().at, 14u);
    EXPECT_STREQ(e.what(), "sim stylus head: sample 14 drives 1500.0 µm, outside the amplifier's ±1000 µm; head retracted");
  }
  EXPECT_TRUE(head.lifted());
  EXPECT_EQ(head.samples(), 10u);  // the refused block was not executed
  const DeviceReport r = head.end_job();
  EXPECT_EQ(r.outcome, DeviceState::failed);
  ASSERT_TRUE(r.fault.has_value());
  head.reset();
  head.begin_job(job(10));  // re-armed
  head.write(constant(10, 1));
  EXPECT_EQ(head.end_job().outcome, DeviceState::done);
}

TEST(SimStylusHead, RefusesNotANumber) {
  SimStylusHead head(quiet());
  head.begin_job(job(10));
  EXPECT_THROW(head.write(constant(10, std::nanf(""))), DeviceFaultError);
}

TEST(SimStylusHead, JobBuffersComeFromTheHeader) {
  SimStylusHead head(quiet());
  EXPECT_THROW(head.begin_job(job(0)), std::invalid_argument);
  SimStylusHeadOptions o = quiet();
  o.max_record_samples = 1000;
  SimStylusHead small(o);
  EXPECT_THROW(small.begin_job(job(1001)), std::invalid_argument);
  small.begin_job(job(1000));
  EXPECT_THROW(small.begin_job(job(1000)), DeviceStateError);  // a job runs
}

TEST(SimStylusHead, SenseNoiseIsReproducible) {
  SimStylusHeadOptions o = quiet();
  o.sense_noise_um = 0.5;
  SimStylusHead a(o), b(o);
  for (SimStylusHead* h : {&a, &b}) {
    h->begin_job(job(1000));
    h->write(constant(1000, 0));
    h->end_job();
  }
  EXPECT_EQ(a.sensed_position_um(), b.sensed_position_um());
  double sum = 0;
  for (float v : a.sensed_position_um()) sum += v * v;
  EXPECT_NEAR(std::sqrt(sum / 1000), 0.5, 0.05);
}

TEST(SimStylusHead, VelocityNoiseIsReproducibleAndIndependent) {
  // A head at rest: the sensed velocity is the coil's velocity noise alone, at its rms, the same
  // for the same seed, other for another, and it leaves the position noise as it was without it.
  SimStylusHeadOptions o = quiet();
  o.sense_noise_um = 0.5;
  o.sense_velocity_noise_um_s = 300;
  SimStylusHeadOptions without = o, reseeded = o;
  without.sense_velocity_noise_um_s = 0;
  reseeded.noise_seed = 2;
  SimStylusHead a(o), b(o), c(without), d(reseeded);
  for (SimStylusHead* h : {&a, &b, &c, &d}) {
    h->begin_job(job(4000));
    h->write(constant(4000, 0));
    h->end_job();
  }
  EXPECT_EQ(a.sensed_velocity_um_s(), b.sensed_velocity_um_s());
  EXPECT_NE(a.sensed_velocity_um_s(), d.sensed_velocity_um_s());
  EXPECT_EQ(a.sensed_position_um(), c.sensed_position_um());
  double sum = 0, cross = 0;
  for (std::size_t k = 0; k < 4000; ++k) {
    sum += a.sensed_velocity_um_s()[k] * a.sensed_velocity_um_s()[k];
    cross += a.sensed_velocity_um_s()[k] * a.sensed_position_um()[k];
  }
  EXPECT_NEAR(std::sqrt(sum / 4000), 300, 15);
  // Uncorrelated with the position noise: |ρ| well inside 4/√n.
  EXPECT_LT(std::abs(cross / 4000 / (300 * 0.5)), 4 / std::sqrt(4000.0));
  for (float v : c.sensed_velocity_um_s()) EXPECT_EQ(v, 0);
  o.sense_velocity_noise_um_s = -1;
  EXPECT_THROW(SimStylusHead{o}, std::invalid_argument);
}

}  // namespace
}  // namespace mark
