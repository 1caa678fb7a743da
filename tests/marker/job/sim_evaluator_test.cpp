// The evaluator passed in instead of asking what the device is (marker/job/sim_evaluator.hpp):
// the simulated scanner as the job's device, and the same scanner as the plant behind an LMC
// device on the emulated board (plan → list packets → the board's own 10 µs clock → scanner).
// The board path is checked against the direct path, which it shares nothing with but the
// plan: the same strokes at the same speed mark the same (class, coverage, dose within the
// board's whole-tick vectors, deviation within the chord tolerance and a field unit).
#include <gtest/gtest.h>

#include <cmath>

#include "driver/lmc/emulated_board.hpp"
#include "driver/lmc/lmc_device.hpp"
#include "driver/lmc/loopback_link.hpp"
#include "driver/sim/quality_class.hpp"
#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"
#include "tests/marker/job/serial_job.hpp"

namespace mark {
namespace {

using mark::test::serial_job;

// The simulated scanner behind an LMC device on the emulated board, on the board's clock at
// 4 × real time. Arcs go to the board as 1 µm chords: at the default 5 µm the chords' own sagitta
// is what separates the two paths (docs/lmc.md), and this test is about the evaluator.
struct BoardPlant {
  explicit BoardPlant(const JobSpec& spec) : plant(simulator_options(spec)), board(board_options()) {
    board.start_clock(4.0);
    lmc::LmcOptions o = lmc::test::quick_options();
    o.field_mm = spec.head.field_mm;
    o.chord_tolerance_mm = 0.001;
    device = std::make_unique<lmc::LmcDevice>(std::make_unique<lmc::LoopbackLink>(board), o);
  }
  ~BoardPlant() {
    device.reset();
    board.stop_clock();
  }
  lmc::BoardOptions board_options() {
    lmc::BoardOptions bo;
    bo.scanner = &plant;
    return bo;
  }
  double dose_total() const {
    double total = 0;
    board.inspect([&] { total = plant.dose().total(); });
    return total;
  }

  SimScanner plant;
  lmc::EmulatedBoard board;
  std::unique_ptr<lmc::LmcDevice> device;
};

JobOptions untimed(MarkEvaluator* evaluator) {
  JobOptions o;
  o.virtual_time = true;
  o.realtime = false;
  o.evaluator = evaluator;
  return o;
}

TEST(SimEvaluator, OnTheScannerItselfFillsQualityPulsesAndCodes) {
  const JobSpec spec = serial_job();
  SimScanner scanner(simulator_options(spec));
  const JobResult none = run_job(spec, untimed(nullptr), scanner);
  EXPECT_FALSE(none.quality);  // the runner asks nothing of the device
  EXPECT_FALSE(none.pulses);
  scanner.reset();
  SimEvaluator evaluator(scanner);
  const JobResult r = run_job(spec, untimed(&evaluator), scanner);
  ASSERT_EQ(r.outcome, JobOutcome::done);
  ASSERT_TRUE(r.quality);
  ASSERT_TRUE(r.pulses);
  EXPECT_EQ(classify(*r.quality), QualityClass::high);
  // The pulse figures are the scanner's own: 300 mm/s at the pen's 30 kHz is 10 µm apart, the
  // widest gap a little more where the lagging beam catches up after a corner.
  EXPECT_EQ(r.pulses->pulses, scanner.pulses().pulses);
  EXPECT_GE(r.pulses->spacing_max_um, 300.0 / r.pulses->frequency_khz - 0.01);
  EXPECT_LT(r.pulses->spacing_max_um, 1.05 * 300.0 / r.pulses->frequency_khz);
  // The same as the free function on the same marks.
  const Quality q = simulated_quality(r, scanner, mark_intent(spec, scanner));
  EXPECT_DOUBLE_EQ(q.max_deviation_um, r.quality->max_deviation_um);
  EXPECT_DOUBLE_EQ(q.coverage, r.quality->coverage);
}

// Dose sufficiency against the material (--dose-reference material): the pen's own figure says
// nothing about a material that needs more than the pen's power / speed; the material's does.
// serial_job marks at 300 mm/s and 100 % power. A material whose reference line (one beam
// diameter wide) is marked at full power at 100 mm/s needs 3× the pen's energy per mm.
TEST(SimEvaluator, DoseAgainstTheMaterialFindsAPenThatPutsDownTooLittle) {
  JobSpec spec = serial_job();
  ASSERT_DOUBLE_EQ(spec.pen.mark_speed_mm_s, 300);
  ASSERT_DOUBLE_EQ(spec.laser.power_pct, 100);
  spec.verify.response.reference_speed_mm_s = 100;  // reference width = beam: spot-wide at 100 mm/s
  ASSERT_NEAR(spec.verify.response.spot_line_speed_mm_s(), 100, 1e-9);
  const auto mark = [&](bool vs_material) {
    spec.verify.dose_vs_material = vs_material;
    SimScanner scanner(simulator_options(spec));
    SimEvaluator evaluator(scanner);
    const JobResult r = run_job(spec, untimed(&evaluator), scanner);
    EXPECT_EQ(r.outcome, JobOutcome::done);
    return r.quality.value_or(Quality{});
  };
  const Quality pen = mark(false);
  const Quality material = mark(true);
  // Judged on the pen: "high", with the material's share reported beside it (a third).
  EXPECT_EQ(classify(pen), QualityClass::high);
  EXPECT_FALSE(pen.dose_vs_material);
  EXPECT_GT(pen.dose_per_mm_fraction, 0.9);
  EXPECT_NEAR(pen.material_dose_per_mm_fraction, pen.dose_per_mm_fraction / 3, 0.01);
  // Judged on the material: the same marks, a third of what it needs, below "good"'s half.
  EXPECT_TRUE(material.dose_vs_material);
  EXPECT_NEAR(material.dose_per_mm_fraction, pen.dose_per_mm_fraction / 3, 0.01);
  EXPECT_DOUBLE_EQ(material.material_dose_per_mm_fraction, material.dose_per_mm_fraction);
  EXPECT_DOUBLE_EQ(material.max_deviation_um, pen.max_deviation_um);
  EXPECT_EQ(classify(material), QualityClass::poor);
  EXPECT_NE(quality_figures(material).find("of the material's"), std::string::npos) << quality_figures(material);
  // A material the pen over-serves (spot-wide at 1000 mm/s, the default) is "high" either way.
  spec.verify.response.reference_speed_mm_s = 1000;
  const Quality served = mark(true);
  EXPECT_NEAR(served.dose_per_mm_fraction, pen.dose_per_mm_fraction * 1000 / 300, 0.05);
  EXPECT_EQ(classify(served), QualityClass::high);
}

TEST(SimEvaluator, BehindAnEmulatedBoardMarksAsTheDirectPath) {
  const JobSpec spec = serial_job();
  SimScanner direct(simulator_options(spec));
  const JobResult d = run_job_simulated(spec, untimed(nullptr), direct);
  ASSERT_EQ(classify(*d.quality), QualityClass::high);
  const double direct_dose = direct.dose().total();

  BoardPlant rig(spec);
  SimEvaluator evaluator =
      SimEvaluator::behind(rig.plant, [&](const std::function<void()>& f) { rig.board.inspect(f); });
  JobOptions o = untimed(&evaluator);
  o.virtual_time = false;  // a board keeps its own clock
  const JobResult b = run_job(spec, o, *rig.device);
  ASSERT_EQ(b.outcome, JobOutcome::done) << (b.fault ? b.fault->message : "");
  ASSERT_TRUE(b.quality);
  ASSERT_TRUE(b.pulses);
  EXPECT_EQ(classify(*b.quality), QualityClass::high);
  EXPECT_EQ(b.quality->coverage, d.quality->coverage);
  const double unit_um = std::sqrt(2.0) * 110 / 65.535;  // a field unit's diagonal
  EXPECT_LE(b.quality->max_deviation_um, d.quality->max_deviation_um + 1 + unit_um);
  const double board_dose = rig.dose_total();
  EXPECT_NEAR(board_dose / direct_dose, 1.0, 0.05);
  std::printf("direct %.2f µm, board %.2f µm max deviation; dose ratio %.4f\n",
              d.quality->max_deviation_um, b.quality->max_deviation_um, board_dose / direct_dose);

  // The next job re-arms the plant: its dose is this job's, not the two added up.
  const JobResult again = run_job(spec, o, *rig.device);
  ASSERT_EQ(again.outcome, JobOutcome::done);
  EXPECT_NEAR(rig.dose_total() / board_dose, 1.0, 0.01);
  EXPECT_EQ(classify(*again.quality), QualityClass::high);

  // A job stopped half way: the board's laser goes off, the figures show a partial mark, and
  // the plant took the board's last samples without a complaint.
  JobOptions stop = o;
  stop.inject = {Injection::Kind::abort, b.commands / 2};
  const JobResult half = run_job(spec, stop, *rig.device);
  EXPECT_EQ(half.outcome, JobOutcome::aborted);
  ASSERT_TRUE(half.quality);
  EXPECT_LT(half.quality->coverage, 0.9);
  EXPECT_LT(rig.dose_total(), 0.9 * board_dose);
  for (const std::string& v : rig.board.violations()) ADD_FAILURE() << v;
}

}  // namespace
}  // namespace mark
