// The whole job on the simulated SL10 head: "SN 42" at 2 mm, 800 mm/s. Bounds measured with
// `marker mark "SN 42" --height 2 --speed 800 --corner C --virtual-time --json` (blanking: max
// 10.8 µm, coverage 0.9825, dose ratio 1.054, overshoot 1.2 µm; delays: 16.7 µm, 0.962, 4.07;
// none: 511 µm, 0.860, 2.32), with a little room.
#include <gtest/gtest.h>

#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "marker/locus/locus_generator.hpp"

namespace mark {
namespace {

JobSpec serial(CornerStrategy corner) {
  JobSpec spec;
  spec.text = "SN 42";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 2;
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, corner, 800);
  return spec;
}

JobResult mark_virtual(CornerStrategy corner) {
  const JobSpec spec = serial(corner);
  JobOptions options;
  options.virtual_time = true;
  SimScanner scanner(simulator_options(spec));
  return run_job_simulated(spec, options, scanner);
}

TEST(JobEndToEnd, BlankingMarksTheSerialWithinMeasuredQuality) {
  const JobResult r = mark_virtual(CornerStrategy::blanking);
  ASSERT_TRUE(r.quality);
  EXPECT_EQ(r.glyphs, 5u);
  EXPECT_EQ(r.strokes, 4u);
  EXPECT_LT(r.quality->max_deviation_um, 12.0);
  EXPECT_LT(r.quality->rms_deviation_um, 5.0);
  EXPECT_GT(r.quality->coverage, 0.975);
  EXPECT_LT(r.quality->dose_ratio_max, 1.10);
  EXPECT_LT(r.quality->overshoot_um, 2.0);
  EXPECT_EQ(r.drain.underrun_events, 0u);
  // Device time is the samples handed to the scanner: the locus, at most the delay line's tail
  // and the drain's closing safe sample.
  const std::uint64_t locus = LocusGenerator::count_samples(r.job.plan.commands, 10e-6);
  EXPECT_GE(r.samples, locus + 1);
  EXPECT_LE(r.samples, locus + r.job.laser_off_ticks + 2);
  EXPECT_EQ(r.outcome, JobOutcome::done);
  EXPECT_EQ(r.ink_marked, 1.0);
  EXPECT_DOUBLE_EQ(r.mark_time_s, r.samples * 10e-6);
}

TEST(JobEndToEnd, BlankingBeatsDelaysBeatsNothing) {
  const JobResult b = mark_virtual(CornerStrategy::blanking);
  const JobResult d = mark_virtual(CornerStrategy::delays);
  const JobResult n = mark_virtual(CornerStrategy::none);
  EXPECT_LT(d.quality->max_deviation_um, 20.0);
  EXPECT_GT(d.quality->dose_ratio_max, 3.0);  // burn-in where the mirrors start from rest
  EXPECT_GT(n.quality->max_deviation_um, 300.0);  // lit while still catching up after jumps
  EXPECT_LT(b.quality->max_deviation_um, d.quality->max_deviation_um);
  EXPECT_GT(b.quality->coverage, d.quality->coverage);
  EXPECT_LT(b.quality->dose_ratio_max, d.quality->dose_ratio_max);
  EXPECT_LT(d.quality->max_deviation_um, n.quality->max_deviation_um);
}

// Real time: the drain is paced at 100 kHz while the producer writes; the scanner sees the same
// samples, so the figures match the virtual-time run exactly, and nothing underruns.
TEST(JobEndToEnd, RealTimeMatchesVirtualTime) {
  const JobSpec spec = serial(CornerStrategy::blanking);
  SimScanner scanner(simulator_options(spec));
  const JobResult rt = run_job_simulated(spec, JobOptions{}, scanner);
  const JobResult vt = mark_virtual(CornerStrategy::blanking);
  EXPECT_EQ(rt.samples, vt.samples);
  EXPECT_EQ(rt.drain.underrun_events, 0u);
  EXPECT_DOUBLE_EQ(rt.quality->max_deviation_um, vt.quality->max_deviation_um);
  EXPECT_DOUBLE_EQ(rt.quality->coverage, vt.quality->coverage);
  // Paced, not faster than the device: 3391 samples at 100 kHz take 34 ms.
  EXPECT_GE(rt.wall_time_s, 0.9 * rt.mark_time_s);
}

}  // namespace
}  // namespace mark
