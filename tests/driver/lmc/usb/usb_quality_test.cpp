// A serial-number job through everything real: layout, plan, the job runner's device program,
// LmcDevice, libusb, usbfs ioctls (umockdev) — into the emulated board, whose 10 µs executor
// feeds the simulated scanner. At the fastest speed at which the direct simulator path is
// "high", the board path is "high" too once its arcs are chorded finely enough (1 µm), with a
// comparable dose; with the default 5 µm chords it deviates by no more than the chord tolerance
// and the field quantisation beyond the direct path — the lag already takes the whole 10 µm
// budget there (its inward cut on a 0.3 mm arc is v²τ²/2R ≈ 10 µm), so the chords' own inward
// sagitta is what separates the two (figures in docs/lmc.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "driver/lmc/usb_discovery.hpp"
#include "driver/sim/quality_class.hpp"
#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"
#include "tests/driver/lmc/usb/umockdev_board.hpp"
#include "tests/marker/job/serial_job.hpp"

namespace mark::lmc {
namespace {

using mark::test::serial_job;

struct Marked {
  Quality quality;
  double dose_total = 0;
  double mark_time_s = 0;
  DeviceReport device;
};

Marked direct(const JobSpec& spec, const QualityReference& ref) {
  JobOptions o;
  o.virtual_time = true;
  SimScanner scanner(simulator_options(spec));
  const JobResult r = run_job_simulated(spec, o, scanner, &ref);
  return {*r.quality, scanner.dose().total(), r.mark_time_s, r.device};
}

// The fastest speed (within 2 %) at which the direct path is of class `level`.
double fastest_direct(const QualityLimits& level, const QualityReference& ref) {
  double lo = 50, hi = 4000;
  if (!meets(direct(serial_job(lo), ref).quality, level)) return 0;
  while (hi / lo > 1.02) {
    const double mid = std::sqrt(lo * hi);
    (meets(direct(serial_job(mid), ref).quality, level) ? lo : hi) = mid;
  }
  return lo;
}

Marked through_board(const JobSpec& spec, const QualityReference& ref, double chord_tolerance_mm) {
  test::Testbed tb;
  SimScanner scanner(simulator_options(spec));
  BoardOptions bo;
  bo.scanner = &scanner;
  EmulatedBoard board(bo);
  test::UmockdevBoard usb(tb.get(), board);
  board.start_clock();
  LmcOptions o = test::quick_options();
  o.field_mm = spec.head.field_mm;
  o.chord_tolerance_mm = chord_tolerance_mm;
  LmcDevice device(open_usb_board(""), o);
  // The scanner is the plant behind the board: its evaluator reads it under the board's lock.
  SimEvaluator evaluator =
      SimEvaluator::behind(scanner, [&](const std::function<void()>& f) { board.inspect(f); }, &ref);
  JobOptions jo;
  jo.realtime = false;
  jo.evaluator = &evaluator;
  const JobResult r = run_job(spec, jo, device);
  EXPECT_EQ(r.outcome, JobOutcome::done) << (r.fault ? r.fault->message : "");
  board.stop_clock();
  const BoardState s = board.state();
  EXPECT_EQ(s.executor.underrun_events, 0u);
  EXPECT_EQ(s.executor.distance_mismatches, 0u);
  EXPECT_TRUE(board.violations().empty());
  EXPECT_TRUE(r.quality);
  return {r.quality.value_or(Quality{}), scanner.dose().total(), double(s.executor.ticks) * 10e-6, r.device};
}

void print_side_by_side(double v, const Marked& d, const Marked& fine, const Marked& coarse) {
  std::printf("%.0f mm/s             %10s %12s %12s\n", v, "direct", "board 1 µm", "board 5 µm");
  const auto row = [](const char* name, double a, double b, double c) {
    std::printf("%-20s %10.4g %12.4g %12.4g\n", name, a, b, c);
  };
  row("max deviation µm", d.quality.max_deviation_um, fine.quality.max_deviation_um, coarse.quality.max_deviation_um);
  row("rms deviation µm", d.quality.rms_deviation_um, fine.quality.rms_deviation_um, coarse.quality.rms_deviation_um);
  row("coverage", d.quality.coverage, fine.quality.coverage, coarse.quality.coverage);
  row("dose ratio", d.quality.dose_ratio_max, fine.quality.dose_ratio_max, coarse.quality.dose_ratio_max);
  row("overshoot µm", d.quality.overshoot_um, fine.quality.overshoot_um, coarse.quality.overshoot_um);
  row("dose total", d.dose_total, fine.dose_total, coarse.dose_total);
  row("device time s", d.mark_time_s, fine.mark_time_s, coarse.mark_time_s);
  row("commands", 0, test::figure(fine.device, "commands"), test::figure(coarse.device, "commands"));
  row("list packets", 0, test::figure(fine.device, "packets"), test::figure(coarse.device, "packets"));
  std::printf("class                %10s %12s %12s\n", std::string(to_string(classify(d.quality))).c_str(),
              std::string(to_string(classify(fine.quality))).c_str(),
              std::string(to_string(classify(coarse.quality))).c_str());
}

TEST(LmcUsbQuality, SerialNumberThroughTheBoardReachesTheDirectPathsClass) {
  const JobSpec probe = serial_job(1000);
  const QualityReference ref(intended_polylines(compile_job(probe).figure));
  const double v = fastest_direct(kHighQuality, ref);
  ASSERT_GT(v, 0) << "the direct path never reaches high";
  const JobSpec spec = serial_job(v);
  const Marked d = direct(spec, ref);
  const Marked fine = through_board(spec, ref, 0.001);
  const Marked coarse = through_board(spec, ref, 0.005);
  print_side_by_side(v, d, fine, coarse);

  EXPECT_EQ(classify(d.quality), QualityClass::high);
  EXPECT_EQ(classify(fine.quality), QualityClass::high);
  // The same strokes at the same speed leave the same dose, within the board's whole-tick
  // vectors and truncated speed words.
  EXPECT_NEAR(fine.dose_total / d.dose_total, 1.0, 0.05);
  EXPECT_NEAR(coarse.dose_total / d.dose_total, 1.0, 0.05);
  // Chords add at most their tolerance, the board's truncation at most a unit's diagonal.
  const double unit_um = std::sqrt(2.0) * 110 / 65.535;
  EXPECT_LE(coarse.quality.max_deviation_um, d.quality.max_deviation_um + 5 + unit_um);
  EXPECT_LE(fine.quality.max_deviation_um, d.quality.max_deviation_um + 1 + unit_um);
  // The device time: the board runs what the direct path ran, plus its 8 ms open-MO delay
  // and whole-tick vectors.
  EXPECT_NEAR(fine.mark_time_s, d.mark_time_s + 0.008, 0.15 * d.mark_time_s);
}

}  // namespace
}  // namespace mark::lmc
