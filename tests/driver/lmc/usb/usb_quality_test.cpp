// A serial-number job through everything real: layout, plan, the job runner's device program,
// LmcDevice, libusb, usbfs ioctls (umockdev) — into the emulated board, whose 10 µs executor
// feeds the simulated scanner. Its quality class must be the direct simulator path's at the
// fastest speed the direct path reaches that class, and its dose comparable.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "driver/lmc/usb_discovery.hpp"
#include "driver/quality_class.hpp"
#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"
#include "tests/driver/lmc/usb/umockdev_board.hpp"

namespace mark::lmc {
namespace {

JobSpec serial_job(double speed_mm_s) {
  JobSpec spec;
  spec.text = "SN 20260042";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 1.5;
  spec.layout.align = Align::center;
  spec.layout.base = Point(0, 0.5);
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, CornerStrategy::blanking, speed_mm_s);
  return spec;
}

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

Marked through_board(const JobSpec& spec, const QualityReference& ref) {
  test::Testbed tb;
  SimScanner scanner(simulator_options(spec));
  BoardOptions bo;
  bo.scanner = &scanner;
  EmulatedBoard board(bo);
  test::UmockdevBoard usb(tb.get(), board);
  board.start_clock();
  LmcOptions o = test::quick_options();
  o.field_mm = spec.head.field_mm;
  LmcDevice device(open_usb_board(""), o);
  JobOptions jo;
  jo.realtime = false;
  const JobResult r = run_job(spec, jo, device);
  EXPECT_EQ(r.outcome, JobOutcome::done) << (r.fault ? r.fault->message : "");
  board.stop_clock();
  const BoardState s = board.state();
  EXPECT_EQ(s.executor.underrun_events, 0u);
  EXPECT_EQ(s.executor.distance_mismatches, 0u);
  EXPECT_TRUE(board.violations().empty());
  return {ref.evaluate(scanner.lit_paths(), scanner.dose()), scanner.dose().total(),
          double(s.executor.ticks) * 10e-6, r.device};
}

TEST(LmcUsbQuality, SerialNumberThroughTheBoardMatchesTheDirectPath) {
  const JobSpec probe = serial_job(1000);
  const QualityReference ref(intended_polylines(compile_job(probe).figure));
  const double v = fastest_direct(kHighQuality, ref);
  ASSERT_GT(v, 0) << "the direct path never reaches high";
  const JobSpec spec = serial_job(v);
  const Marked d = direct(spec, ref);
  const Marked b = through_board(spec, ref);
  std::printf("speed %.0f mm/s       %10s %10s\n", v, "direct", "LMC board");
  std::printf("max deviation µm   %10.2f %10.2f\n", d.quality.max_deviation_um, b.quality.max_deviation_um);
  std::printf("rms deviation µm   %10.2f %10.2f\n", d.quality.rms_deviation_um, b.quality.rms_deviation_um);
  std::printf("coverage           %10.4f %10.4f\n", d.quality.coverage, b.quality.coverage);
  std::printf("dose ratio         %10.3f %10.3f\n", d.quality.dose_ratio_max, b.quality.dose_ratio_max);
  std::printf("overshoot µm       %10.2f %10.2f\n", d.quality.overshoot_um, b.quality.overshoot_um);
  std::printf("dose total         %10.4g %10.4g\n", d.dose_total, b.dose_total);
  std::printf("device time s      %10.4f %10.4f\n", d.mark_time_s, b.mark_time_s);
  for (const auto& [k, val] : b.device.figures) std::printf("  board %s = %g\n", k.c_str(), val);
  EXPECT_EQ(classify(d.quality), QualityClass::high);
  EXPECT_EQ(classify(b.quality), QualityClass::high);
}

}  // namespace
}  // namespace mark::lmc
