// The simulated laser's source settings: the dose is proportional to the pen's power (the lit
// path is not), and the pulse train at the pen's frequency lands pulses v/f apart along the
// beam's path, with their overlap against the head's spot diameter.
#include <gtest/gtest.h>

#include "driver/sim/sim_scanner.hpp"
#include "tests/driver/command_streams.hpp"

namespace mark {
namespace {

using test::Stream;

JobHeader header_with(double power_pct, double frequency_khz) {
  JobHeader h;
  DevicePen pen;
  pen.laser.power_pct = power_pct;
  pen.laser.frequency_khz = frequency_khz;
  h.pens.push_back(pen);
  h.field_mm = 110;
  return h;
}

// A settled jump to (−3, 0), a lit line to (3, 0) at v, a pause with the laser off.
Stream laser_line_at(double v) {
  Stream s;
  s.step_to({-3, 0}, 300).move({3, 0}, v, true).hold(100, false);
  return s;
}

struct LaserMarked {
  double dose;
  std::size_t lit_runs;
  double lit_length_mm;
  PulseFigures pulses;
  DeviceFigures figures;
};

LaserMarked mark(const Stream& s, const JobHeader& h, HeadModel head = head_sl10()) {
  SimScannerOptions o;
  o.head = head;
  SimScanner sim(o);
  sim.begin_job(h);
  sim.write(s.samples());
  const DeviceReport r = sim.end_job();
  LaserMarked m{sim.dose().total(), sim.lit_paths().runs.size(), 0, sim.pulses(), r.figures};
  for (const auto& run : sim.lit_paths().runs)
    for (std::size_t i = 1; i < run.size(); ++i) m.lit_length_mm += norm(run[i] - run[i - 1]);
  return m;
}

double figure(const DeviceFigures& f, const std::string& name) {
  for (const auto& [k, v] : f)
    if (k == name) return v;
  ADD_FAILURE() << "no device figure " << name;
  return 0;
}

TEST(SimLaser, DoseIsProportionalToThePensPower) {
  const Stream s = laser_line_at(1000);
  const LaserMarked full = mark(s, header_with(100, 30));
  const LaserMarked half = mark(s, header_with(50, 30));
  const LaserMarked tenth = mark(s, header_with(10, 30));
  // 6 mm at 1000 mm/s: 6 ms lit at full power.
  EXPECT_NEAR(full.dose, 6e-3, 1e-8);
  EXPECT_NEAR(half.dose / full.dose, 0.5, 0.005);
  EXPECT_NEAR(tenth.dose / full.dose, 0.1, 0.001);
  // Where the beam marked does not depend on the power.
  EXPECT_EQ(half.lit_runs, 1u);
  EXPECT_EQ(tenth.lit_runs, full.lit_runs);
  EXPECT_NEAR(tenth.lit_length_mm, full.lit_length_mm, 1e-9);
  EXPECT_DOUBLE_EQ(figure(half.figures, "power_pct"), 50);
  // A job without a pen (samples written straight) marks at full power.
  SimScanner bare;
  bare.write(s.samples());
  EXPECT_NEAR(bare.dose().total(), full.dose, 1e-12);
}

TEST(SimLaser, PulsesLandVOverFApart) {
  // 1000 mm/s at 30 kHz: 33.3 µm, 17 % overlap on the 40 µm spot (dynamics.md §4.2).
  const LaserMarked m = mark(laser_line_at(1000), header_with(100, 30));
  EXPECT_NEAR(m.pulses.spacing_max_um, 1000.0 / 30, 0.01);
  EXPECT_NEAR(m.pulses.overlap(), 1 - (1000.0 / 30) / 40, 1e-3);
  EXPECT_FALSE(m.pulses.separate_dots());
  // 6 ms lit at 30 kHz: 180 periods, the first pulse as the gate opens.
  EXPECT_NEAR(static_cast<double>(m.pulses.pulses), 181, 1);
  // The beam starts the line from rest (no run-in here), so the mean gap is a little shorter.
  EXPECT_LT(m.pulses.spacing_mean_um, m.pulses.spacing_max_um);
  EXPECT_GT(m.pulses.spacing_mean_um, 0.9 * m.pulses.spacing_max_um);
  EXPECT_NEAR(figure(m.figures, "pulse_spacing_um"), m.pulses.spacing_max_um, 1e-12);
  EXPECT_NEAR(figure(m.figures, "pulse_overlap_fraction"), m.pulses.overlap(), 1e-12);

  // 400 mm/s at 20 kHz: 20 µm apart, half overlapping.
  const LaserMarked slow = mark(laser_line_at(400), header_with(100, 20));
  EXPECT_NEAR(slow.pulses.spacing_max_um, 20, 0.01);
  EXPECT_NEAR(slow.pulses.overlap(), 0.5, 1e-3);
}

TEST(SimLaser, PulsesFurtherApartThanTheSpotAreSeparateDots) {
  // 2000 mm/s at 30 kHz: 66.7 µm apart on a 40 µm spot — a dotted line.
  const LaserMarked m = mark(laser_line_at(2000), header_with(100, 30));
  EXPECT_NEAR(m.pulses.spacing_max_um, 2000.0 / 30, 0.02);
  EXPECT_NEAR(m.pulses.overlap(), 1 - (2000.0 / 30) / 40, 1e-3);
  EXPECT_TRUE(m.pulses.separate_dots());
  // The same speed on a head with a 70 µm spot overlaps again.
  HeadModel wide = head_sl10();
  wide.spot_diameter_um = 70;
  const LaserMarked w = mark(laser_line_at(2000), header_with(100, 30), wide);
  EXPECT_NEAR(w.pulses.overlap(), 1 - (2000.0 / 30) / 70, 1e-3);
  EXPECT_FALSE(w.pulses.separate_dots());
}

TEST(SimLaser, EachLitRunStartsItsOwnPulseTrain) {
  // Two lit lines with a gap: the jump between them is not a pulse gap.
  Stream s;
  s.step_to({-3, 0}, 300).move({-1, 0}, 1000, true).move({1, 0}, 1000, false).move({3, 0}, 1000, true)
      .hold(100, false);
  const LaserMarked m = mark(s, header_with(100, 50));
  EXPECT_NEAR(m.pulses.spacing_max_um, 20, 0.01);  // not the 2 mm jump
}

TEST(SimLaser, RefusesAPenOutsideTheSourcesRange) {
  SimScanner sim;
  EXPECT_THROW(sim.begin_job(header_with(150, 30)), DeviceFaultError);
  EXPECT_THROW(sim.begin_job(header_with(50, 0)), DeviceFaultError);
  EXPECT_EQ(sim.status().state, DeviceState::idle);
  sim.begin_job(header_with(50, 30));
  EXPECT_EQ(sim.status().state, DeviceState::running);
}

}  // namespace
}  // namespace mark
