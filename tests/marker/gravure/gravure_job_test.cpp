// The whole gravure job on the simulated head: a step wedge and fine line-work engraved through
// the line memory and the drain, with the filters and without. Filtering must bring the depth
// error against the intended toolpath down by at least a factor of 3 — with filters designed for
// the head's nameplate values, and with filters from the automatic tuning on a head that has
// drifted from them.
#include "marker/gravure/gravure_job.hpp"

#include <gtest/gtest.h>

#include "tests/marker/gravure/test_images.hpp"

namespace mark {
namespace {

GravureJobSpec wedge_job() {
  GravureJobSpec spec;
  GrayImage mask;
  spec.image = test::wedge_and_lines(280, 112, &mask);
  spec.mask = mask;
  return spec;
}

TEST(GravureJob, FilteringCutsTheDepthErrorOfAStepWedgeAndLineWork) {
  const GravureReport r = run_gravure_job(wedge_job());
  // 10 mm × 4 mm at 70 lines/cm: 28 tracks of 70 cells, 32 samples a cell.
  EXPECT_EQ(r.layout.tracks, 28u);
  EXPECT_EQ(r.layout.cells_per_track, 70u);
  EXPECT_EQ(r.cells, 1960u);
  EXPECT_EQ(r.samples, 1960u * 32);
  // Every sample of the job and the drain's closing safe sample, at 5 µs.
  EXPECT_EQ(r.filtered.run.report.samples_out, 1960u * 32 + 1);
  EXPECT_NEAR(r.filtered.run.report.device_time_s, (1960 * 32 + 1) * 5e-6, 1e-9);
  EXPECT_EQ(r.filtered.run.report.outcome, DeviceState::done);
  // Every kind of cell is in the artwork.
  EXPECT_GT(r.counts.white, 0u);
  EXPECT_GT(r.counts.single, 0u);
  EXPECT_GT(r.counts.channel, 0u);
  EXPECT_GT(r.counts.split, 100u);
  EXPECT_EQ(r.counts.line_work, 14u * 70);
  ASSERT_TRUE(r.unfiltered.has_value());
  const double filtered = r.filtered.depth_error.rms_um, raw = r.unfiltered->depth_error.rms_um;
  EXPECT_GE(raw / filtered, 3) << "filtered " << filtered << " µm, unfiltered " << raw << " µm";
  EXPECT_LT(filtered, 1.0);  // µm rms against cells up to 40 µm deep
  EXPECT_GT(raw, 5.0);       // the bare head rings
  EXPECT_LT(r.filtered.cell_error.volume_rms_pct, 0.25 * r.unfiltered->cell_error.volume_rms_pct);
  EXPECT_EQ(r.engraved_um.size(), r.samples + 1);  // + the drain's closing safe sample
  EXPECT_EQ(r.intended_um.size(), r.samples);
}

TEST(GravureJob, AutoTuningFixesADriftedHead) {
  GravureJobSpec spec = wedge_job();
  spec.head.head = {{{1700, 0.07, 0.8}, {5800, 0.035, 0.2}}};
  const GravureReport nominal = run_gravure_job(spec);
  spec.filters = FilterChoice::tuned;
  const GravureReport tuned = run_gravure_job(spec);
  ASSERT_TRUE(tuned.tuning.has_value());
  EXPECT_TRUE(tuned.tuning->within_tolerance);
  EXPECT_NEAR(tuned.design_head.modes[0].freq_hz, 1700, 34);
  EXPECT_NEAR(tuned.design_head.modes[1].freq_hz, 5800, 116);
  EXPECT_GE(tuned.unfiltered->depth_error.rms_um / tuned.filtered.depth_error.rms_um, 3);
  // Nominal filters on the drifted head help, the tuned ones several times more.
  EXPECT_LT(tuned.filtered.depth_error.rms_um, 0.25 * nominal.filtered.depth_error.rms_um);
}

TEST(GravureJob, FiltersOffRunsOnceAndReportsNoComparison) {
  GravureJobSpec spec = wedge_job();
  spec.filters = FilterChoice::off;
  const GravureReport r = run_gravure_job(spec);
  EXPECT_FALSE(r.unfiltered.has_value());
  EXPECT_TRUE(r.bank.sections.empty());
  EXPECT_GT(r.filtered.depth_error.rms_um, 5);
}

TEST(GravureJob, AStopLiftsTheStylusAndEndsTheJob) {
  GravureJobSpec spec = wedge_job();
  spec.run.stop_at = 5000;  // as if Ctrl-C came at sample 5000
  const GravureReport r = run_gravure_job(spec);
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(r.filtered.run.drain.end, DrainEnd::cancelled);
  EXPECT_EQ(r.filtered.run.report.outcome, DeviceState::aborted);
  EXPECT_EQ(r.filtered.run.stopped_at, 5000u);
  EXPECT_EQ(r.filtered.run.report.samples_out, 5001u);  // and one safe sample
  // Nothing is cut after the stop, though the job was in the middle of the wedge.
  ASSERT_EQ(r.engraved_um.size(), 5001u);
  EXPECT_EQ(r.engraved_um.back(), 0.0f);
  EXPECT_FALSE(r.unfiltered.has_value());
}

TEST(GravureJob, AJobEndsOnTheLiftedSafeSample) {
  GravureJobSpec spec;
  spec.image = GrayImage{28, 28, std::vector<float>(28 * 28, 0.0f)};  // 1 × 1 mm, all black
  spec.compare_unfiltered = false;
  const GravureReport r = run_gravure_job(spec);
  ASSERT_EQ(r.engraved_um.size(), r.samples + 1);
  // The last cell is black, its channel still in the copper at the job's last sample; the safe
  // sample after it retracts the head.
  EXPECT_GT(r.intended_um.back(), 0.0f);
  EXPECT_EQ(r.engraved_um.back(), 0.0f);
}

}  // namespace
}  // namespace mark
