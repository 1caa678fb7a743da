// The parts of a series compiled incrementally (JobCompiler) equal a fresh compile_job, start
// from where the mirrors are, and keep every refusal; passes repeat the strokes; the pen's laser
// settings reach the device (the simulator's dose, a board's pen).
#include <gtest/gtest.h>

#include <algorithm>

#include "base/error.hpp"
#include "fonts/catalog.hpp"
#include "marker/job/device_program.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job_compiler.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "tests/marker/recording_command_device.hpp"
#include "tests/marker/param_print.hpp"

namespace mark {
namespace {

JobSpec series_spec(CornerStrategy corner = CornerStrategy::blanking) {
  JobSpec spec;
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 3;
  spec.layout.base = Point(-20, 0);
  spec.pen = pen_for_head(spec.head, corner, 800);
  return spec;
}

void expect_same(const CompiledJob& a, const CompiledJob& b) {
  ASSERT_EQ(a.plan.commands.size(), b.plan.commands.size());
  for (std::size_t i = 0; i < a.plan.commands.size(); ++i) {
    EXPECT_EQ(a.plan.commands[i].kind, b.plan.commands[i].kind) << i;
    EXPECT_EQ(a.plan.commands[i].role, b.plan.commands[i].role) << i;
    EXPECT_LT((a.plan.commands[i].start() - b.plan.commands[i].start()).norm(), 1e-12) << i;
    EXPECT_LT((a.plan.commands[i].end() - b.plan.commands[i].end()).norm(), 1e-12) << i;
    EXPECT_DOUBLE_EQ(a.plan.commands[i].speed_mm_s, b.plan.commands[i].speed_mm_s) << i;
    EXPECT_EQ(a.plan.commands[i].dwell_ticks, b.plan.commands[i].dwell_ticks) << i;
  }
  EXPECT_EQ(a.plan.strokes, b.plan.strokes);
  EXPECT_NEAR(a.plan.jump_length_mm, b.plan.jump_length_mm, 1e-9);
  EXPECT_EQ(a.figure.glyphs.size(), b.figure.glyphs.size());
  EXPECT_EQ(a.laser_on_ticks, b.laser_on_ticks);
  EXPECT_EQ(a.laser_off_ticks, b.laser_off_ticks);
  EXPECT_EQ(a.level, b.level);
}

class Series : public testing::TestWithParam<CornerStrategy> {};

TEST_P(Series, EqualsAFreshCompileAtEveryPartAndLevel) {
  for (DeviceLevel level : {DeviceLevel::samples, DeviceLevel::commands}) {
    JobSpec spec = series_spec(GetParam());
    JobCompiler compiler(spec, level);
    for (const char* text : {"SN 2026-A17-00004711", "SN 2026-A17-00004712", "SN 2026-A17-00004799",
                             "SN 2026-A17-00004799", "SN 2026-A18-00000001"}) {
      spec.text = text;
      expect_same(compiler.compile(text), compile_job(spec, level));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Corners, Series,
                         testing::Values(CornerStrategy::blanking, CornerStrategy::delays,
                                         CornerStrategy::none),
                         [](const testing::TestParamInfo<CornerStrategy>& info) {
                           return std::string(to_string(info.param));
                         });

TEST(JobCompiler, OnlyTheChangedGlyphsArePlannedAgain) {
  JobCompiler compiler(series_spec(), DeviceLevel::samples);
  compiler.compile("SN 2026-A17-00004711");
  EXPECT_EQ(compiler.replanned_glyphs(), 20u);
  compiler.compile("SN 2026-A17-00004722");
  EXPECT_EQ(compiler.replanned_glyphs(), 2u);
}

TEST(JobCompiler, PlansFromWhereTheMirrorsAre) {
  JobSpec spec = series_spec();
  JobCompiler compiler(spec, DeviceLevel::samples);
  const CompiledJob first = compiler.compile("SN 1");
  const Point end = first.plan.commands.back().end();
  const CompiledJob next = compiler.compile("SN 2", end);
  // The first jump leaves from where the last part ended, not from the field centre.
  EXPECT_EQ(next.plan.commands.front().kind, CommandKind::jump);
  EXPECT_LT((next.plan.commands.front().start() - end).norm(), 1e-12);
  EXPECT_LT((next.plan.home - end).norm(), 1e-12);
  // … and equals planning that part whole from there.
  spec.text = "SN 2";
  const Figure figure = layout_text(spec.text, *spec.font, spec.layout);
  const Plan whole = plan_figure(figure, spec.pen, spec.order, end);
  ASSERT_EQ(next.plan.commands.size(), whole.commands.size());
  EXPECT_NEAR(next.plan.jump_length_mm, whole.jump_length_mm, 1e-9);
  // Back at the centre it is the plain compile again.
  expect_same(compiler.compile("SN 3"), compile_job([&] { spec.text = "SN 3"; return spec; }(),
                                                    DeviceLevel::samples));
}

TEST(JobCompiler, RefusesLikeCompileJobAndCarriesOn) {
  JobSpec spec = series_spec();
  spec.layout.base = Point(40, 0);
  JobCompiler compiler(spec, DeviceLevel::samples);
  EXPECT_NO_THROW(compiler.compile("SN 1"));
  try {
    compiler.compile("SN 1000000000");  // runs past the field's right edge at 55 mm
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the text layout leaves the field"), std::string::npos) << e.what();
  }
  EXPECT_THROW(compiler.compile(""), InputError);
  EXPECT_THROW(compiler.compile("SN \u00e6"), InputError);  // no such glyph
  spec.text = "SN 2";
  expect_same(compiler.compile("SN 2"), compile_job(spec));
  spec.passes = 0;
  EXPECT_THROW(compile_job(spec), InputError);
}

TEST(Passes, RepeatTheStrokesWithOneJumpBack) {
  JobSpec spec = series_spec();
  spec.text = "AB";
  const CompiledJob one = compile_job(spec);
  spec.passes = 3;
  const CompiledJob three = compile_job(spec);
  EXPECT_EQ(three.plan.strokes, 3 * one.plan.strokes);
  EXPECT_EQ(three.plan.count(CommandRole::stroke), 3 * one.plan.count(CommandRole::stroke));
  // Every pass after the first: its commands less the jump from home, plus one jump back.
  EXPECT_EQ(three.plan.commands.size(), one.plan.commands.size() * 3);
  double lit_one = 0, lit_three = 0;
  for (const Command& c : one.plan.commands)
    if (c.laser()) lit_one += c.length_mm();
  for (const Command& c : three.plan.commands)
    if (c.laser()) lit_three += c.length_mm();
  EXPECT_NEAR(lit_three, 3 * lit_one, 1e-9);
  // The jump back runs from the end of a pass to where the first jump from home landed.
  const Command& back = three.plan.commands[one.plan.commands.size()];
  EXPECT_EQ(back.kind, CommandKind::jump);
  EXPECT_LT((back.start() - one.plan.commands.back().end()).norm(), 1e-12);
  EXPECT_LT((back.end() - one.plan.commands.front().end()).norm(), 1e-12);
  // Jumps: home to the first stroke once, then per further pass last stroke end → first start.
  const auto is_stroke = [](const Command& c) { return c.role == CommandRole::stroke; };
  const Point first = std::find_if(one.plan.commands.begin(), one.plan.commands.end(), is_stroke)->start();
  const Point last = std::find_if(one.plan.commands.rbegin(), one.plan.commands.rend(), is_stroke)->end();
  EXPECT_NEAR(three.plan.jump_length_mm,
              3 * one.plan.jump_length_mm + 2 * ((first - last).norm() - first.norm()), 1e-9);
  // Mirror time: three times the pass, plus two jumps back.
  EXPECT_NEAR(three.plan.duration_s(),
              3 * one.plan.duration_s() - 2 * one.plan.commands.front().length_mm() / spec.pen.jump_speed_mm_s +
                  2 * back.length_mm() / spec.pen.jump_speed_mm_s,
              1e-9);
}

TEST(JobLaser, TheSimulatorsDoseFollowsThePensPower) {
  JobSpec spec = series_spec();
  spec.text = "SN 41";
  JobOptions options;
  options.virtual_time = true;
  double dose[2];
  for (int i = 0; i < 2; ++i) {
    spec.laser.power_pct = i == 0 ? 100 : 50;
    SimScanner sim(simulator_options(spec));
    const JobResult r = run_job_simulated(spec, options, sim);
    ASSERT_EQ(r.outcome, JobOutcome::done);
    dose[i] = sim.dose().total();
    // Where it marked does not depend on the power.
    EXPECT_EQ(r.quality->coverage, 1.0);
  }
  EXPECT_NEAR(dose[1] / dose[0], 0.5, 0.005);
}

TEST(JobLaser, PassesDoubleTheDose) {
  JobSpec spec = series_spec();
  spec.text = "SN 41";
  JobOptions options;
  options.virtual_time = true;
  SimScanner once(simulator_options(spec));
  run_job(spec, options, once);
  spec.passes = 2;
  SimScanner twice(simulator_options(spec));
  const JobResult r = run_job_simulated(spec, options, twice);
  EXPECT_NEAR(twice.dose().total() / once.dose().total(), 2.0, 0.01);
  EXPECT_EQ(r.quality->coverage, 1.0);
}

TEST(JobLaser, ABoardGetsThePensLaserSettingsAndEveryPass) {
  JobSpec spec = series_spec();
  spec.text = "AB";
  spec.laser = {60, 45, 200};
  spec.passes = 2;
  test::RecordingCommandDevice board;
  const JobResult r = run_compiled_job(spec, JobCompiler(spec, DeviceLevel::commands).compile("AB"),
                                       JobOptions{}, board);
  ASSERT_EQ(r.outcome, JobOutcome::done);
  ASSERT_EQ(board.headers.size(), 1u);
  const LaserSettings& l = board.headers[0].pens.at(0).laser;
  EXPECT_DOUBLE_EQ(l.power_pct, 60);
  EXPECT_DOUBLE_EQ(l.frequency_khz, 45);
  EXPECT_DOUBLE_EQ(l.pulse_width_ns, 200);
  const DeviceProgram one = device_program(compile_job([&] { spec.passes = 1; return spec; }(),
                                                       DeviceLevel::commands).plan,
                                           spec.laser, board.describe());
  double lit = 0;
  for (std::size_t i = 0; i < board.received.size(); ++i)
    if (board.received[i].op == DeviceOp::mark) ++lit;
  double lit_one = 0;
  for (const DeviceCommand& c : one.commands)
    if (c.op == DeviceOp::mark) ++lit_one;
  EXPECT_EQ(lit, 2 * lit_one);
}

TEST(JobLaser, AJobCompiledForAnotherLevelIsRefused) {
  JobSpec spec = series_spec();
  spec.text = "AB";
  test::RecordingCommandDevice board;
  try {
    run_compiled_job(spec, compile_job(spec, DeviceLevel::samples), JobOptions{}, board);
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "the job was compiled for a sample-level device; recording board is command-level");
  }
  EXPECT_TRUE(board.headers.empty());
}

}  // namespace
}  // namespace mark
