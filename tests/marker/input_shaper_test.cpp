// The input shaper (marker/plan/input_shaper.hpp, marker/locus/shaped_locus.hpp): its taps
// cancel the resonance they are designed for and pass a ramp; the shaped locus delays the laser
// by exactly its whole ticks; and on the simulator, whose 10 kHz mirror resonance the planner's
// model does not have, it turns a feed-forward pen that marks "poor" into one that marks "high" —
// on the resonant plant, on the exact one and on resonances 10 % below and 20 % above the one
// it was told.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "base/error.hpp"
#include "driver/sim/quality_class.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "fonts/catalog.hpp"
#include "marker/cli/plant_option.hpp"
#include "marker/head/head_fit.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "marker/locus/locus_generator.hpp"
#include "marker/plan/input_shaper.hpp"
#include "tests/marker/cps_workload.hpp"

namespace mark {
namespace shaper_test {

PenRules planned_rules(bool feed_forward) {
  PenRules r;
  r.lookahead = true;
  r.feed_forward = feed_forward;
  return r;
}

Pen shaped_pen(double hz, ShaperKind kind, double zeta = 0.02) {
  Pen pen;
  pen.lookahead = true;
  pen.shaper_hz = hz;
  pen.shaper_zeta = zeta;
  pen.shaper = kind;
  return pen;
}

// The ringing a unit step leaves in a mode of frequency `hz` and damping ζ after passing
// through the taps, against the unshaped step's: the taps' response at the mode's damped
// frequency, each weighted by how much the ringing it starts has decayed by the last one.
double residual_share(const InputShaper& s, double tick_s, double hz, double zeta) {
  const double wn = 2 * std::numbers::pi * hz, wd = wn * std::sqrt(1 - zeta * zeta);
  const double end = static_cast<double>(s.taps.size() - 1) * tick_s;
  std::complex<double> sum = 0;
  for (std::size_t j = 0; j < s.taps.size(); ++j) {
    const double t = static_cast<double>(j) * tick_s;
    sum += s.taps[j] * std::exp(-zeta * wn * (end - t)) * std::polar(1.0, wd * t);
  }
  return std::abs(sum);
}

TEST(InputShaperDesign, TheTapsSumToOneAndCancelTheirResonance) {
  for (ShaperKind kind : {ShaperKind::zv, ShaperKind::zvd}) {
    const Pen pen = shaped_pen(10000, kind);
    const InputShaper s = design_input_shaper(pen);
    ASSERT_TRUE(s.active());
    double sum = 0;
    for (double w : s.taps) {
      EXPECT_GE(w, 0);
      sum += w;
    }
    EXPECT_NEAR(sum, 1, 1e-12);
    // Half a period of 10 kHz is 5 ticks of 10 µs: ZV spans 5 ticks (a sliver on the 6th from
    // ζ's longer damped period), ZVD 10.
    EXPECT_EQ(s.taps.size(), kind == ShaperKind::zv ? 7u : 12u);
    EXPECT_EQ(s.delay_ticks, kind == ShaperKind::zv ? 2u : 5u);
    EXPECT_LT(residual_share(s, pen.tick_s, 10000, 0.02), 0.005) << to_string(kind);
    // Off the designed resonance: ZVD leaves less than ZV.
    const double zv_off = residual_share(design_input_shaper(shaped_pen(10000, ShaperKind::zv)), 10e-6, 11500, 0.02);
    const double zvd_off = residual_share(design_input_shaper(shaped_pen(10000, ShaperKind::zvd)), 10e-6, 11500, 0.02);
    EXPECT_LT(zvd_off, zv_off);
    EXPECT_LT(zvd_off, 0.06);
  }
  // A resonance between ticks (9 kHz: 5.56 ticks) is split between the ticks around it and
  // still cancelled to within a few per cent.
  const InputShaper off_grid = design_input_shaper(shaped_pen(9000, ShaperKind::zv));
  EXPECT_LT(residual_share(off_grid, 10e-6, 9000, 0.02), 0.03);
  EXPECT_GT(residual_share(off_grid, 10e-6, 9000, 0.02), 0);
}

TEST(InputShaperDesign, NoShaperLeavesThePensFeedForward) {
  Pen pen;
  pen.ff_lag_s = 120e-6;
  const InputShaper s = design_input_shaper(pen);
  EXPECT_FALSE(s.active());
  EXPECT_EQ(s.tail_ticks(), 0u);
  EXPECT_EQ(s.lag_s, 120e-6);
  EXPECT_EQ(s.inertia_s2, 0);
  // With one: ZV's impulses 1 : K half a damped period apart (5.001 ticks), their mean delay
  // A·half (A = K / (1 + K), 2.42 ticks) rounded to 2 ticks moves onto the lag, and half their
  // variance A·(1 − A)·half² comes off the inertia term (input_shaper.cpp's second-order terms).
  pen.shaper_hz = 10000;
  const InputShaper z = design_input_shaper(pen);
  const double root = std::sqrt(1 - 0.02 * 0.02), K = std::exp(-0.02 * std::numbers::pi / root);
  const double A = K / (1 + K), half = 0.5 / (10000 * root), mean = A * half;
  const double delta = 2 * 10e-6 - mean, variance = A * (1 - A) * half * half;
  EXPECT_EQ(z.delay_ticks, 2u);
  EXPECT_NEAR(z.lag_s, 120e-6 - delta, 1e-9);
  EXPECT_NEAR(z.inertia_s2, -delta * 120e-6 + 0.5 * delta * delta - 0.5 * variance, 1e-12);
}

// The planned locus of a short lit text, shaped and not.
std::vector<ScanSample> locus_of(const Pen& pen) {
  JobSpec spec;
  spec.text = "O8";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 1;
  spec.head = head_sl10();
  spec.pen = pen;
  const CompiledJob job = compile_job(spec);
  LocusGenerator g(job.plan);
  std::vector<ScanSample> out(LocusGenerator::count_samples(job.plan) + 10);
  std::size_t n = 0;
  while (std::size_t got = g.generate(out.data() + n, 7)) n += got;  // small blocks: the history crosses them
  EXPECT_TRUE(g.done());
  out.resize(n);
  return out;
}

TEST(ShapedLocus, TheLaserIsDelayedByTheWholeTicksAndTheCommandComesToRest) {
  Pen pen = pen_for_profile(datasheet_profile(head_sl10()), CornerStrategy::none, 2000, 10e-6,
                            planned_rules(true));
  const std::vector<ScanSample> plain = locus_of(pen);
  pen.shaper_hz = 10000;
  const InputShaper s = design_input_shaper(pen);
  const std::vector<ScanSample> shaped = locus_of(pen);
  ASSERT_EQ(shaped.size(), plain.size() + s.tail_ticks());
  std::size_t lit = 0;
  for (std::size_t k = 0; k < shaped.size(); ++k) {
    const bool want = k >= s.delay_ticks && k - s.delay_ticks < plain.size() && plain[k - s.delay_ticks].laser;
    ASSERT_EQ(shaped[k].laser, want) << "sample " << k;
    if (want) {
      EXPECT_EQ(shaped[k].power, plain[k - s.delay_ticks].power);
    }
    lit += want;
  }
  EXPECT_GT(lit, 100u);
  // The last samples: every tap on the planned end, so the command rests on it.
  EXPECT_FLOAT_EQ(shaped.back().x_mm, plain.back().x_mm);
  EXPECT_FLOAT_EQ(shaped.back().y_mm, plain.back().y_mm);
}

// check_pen's refusal of the pen ("" when it takes it).
std::string pen_refusal(const Pen& pen) {
  try {
    check_pen(pen, head_sl10());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ShapedLocus, AShaperWithoutTheLookAheadPlannerOrAboveAQuarterOfTheTickRateIsRefused) {
  Pen pen;
  pen.shaper_hz = 10000;
  EXPECT_NE(pen_refusal(pen).find("--lookahead"), std::string::npos) << pen_refusal(pen);
  pen = pen_for_profile(datasheet_profile(head_sl10()), CornerStrategy::none, 2000, 10e-6, planned_rules(false));
  pen.shaper_hz = 30000;
  EXPECT_NE(pen_refusal(pen).find("--shaper-hz 30000 Hz"), std::string::npos) << pen_refusal(pen);
  EXPECT_NE(pen_refusal(pen).find("at most 25000 Hz"), std::string::npos) << pen_refusal(pen);
  pen.shaper_hz = 25000;
  EXPECT_EQ(pen_refusal(pen), "");
}

// The 62 characters of cps on SL10, 5000 mm/s with accelerations of 1.2e7 mm/s² (465 cps),
// fed forward by the identified model, MOPA pulses at 250 kHz (20 µm apart on the 40 µm spot).
Quality mark_fast(const Plant& plant, double shaper_hz) {
  JobSpec spec = test::cps_characters_spec();
  spec.pen = pen_for_profile(test::identified_sl10(), CornerStrategy::none, 5000, 10e-6,
                             planned_rules(true));
  spec.pen.accel_mm_s2 = spec.pen.curve_accel_mm_s2 = 1.2e7;
  spec.pen.jump_accel_mm_s2 = 1.6e7;
  spec.pen.min_lit_speed_mm_s = 500;
  spec.pen.shaper_hz = shaper_hz;
  spec.laser.source = LaserSource::mopa;
  spec.laser.frequency_khz = 250;
  const JobResult j = test::mark_on_plant(spec, plant);
  EXPECT_GT(62 / j.mark_time_s, 440);
  return *j.quality;
}

TEST(ShapedMark, TheShaperTakesOutTheResonanceTheModelDoesNotHave) {
  const Plant resonant = cli::parse_plant_option("resonance_hz=10000");
  const Quality unshaped = mark_fast(resonant, 0);
  EXPECT_EQ(classify(unshaped), QualityClass::poor);
  EXPECT_GT(unshaped.max_deviation_um, 15);  // 18.8 µm in this build
  const Quality shaped = mark_fast(resonant, 10000);
  EXPECT_EQ(classify(shaped), QualityClass::high);
  EXPECT_LT(shaped.max_deviation_um, 5);  // 3.2 µm
  // The head without the resonance, shaped all the same: the smoothing is in the feed-forward,
  // so the mark stays "high" (4.3 µm; 0.6 µm unshaped).
  const Quality exact = mark_fast({}, 10000);
  EXPECT_EQ(classify(exact), QualityClass::high);
  EXPECT_LT(exact.max_deviation_um, 6);
}

TEST(ShapedMark, AResonanceTenPercentBelowOrTwentyAboveTheShapersStillMarksHigh) {
  for (const char* plant : {"resonance_hz=9000", "resonance_hz=12000"}) {
    const Quality q = mark_fast(cli::parse_plant_option(plant), 10000);
    EXPECT_EQ(classify(q), QualityClass::high) << plant << ": " << q.max_deviation_um << " µm";
  }
}

}  // namespace shaper_test
}  // namespace mark
