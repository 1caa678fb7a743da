// Refusals before the first sample, each one line naming the input: an empty text, a job that
// leaves the field (the figure plus its blanking lines), a speed or tick outside the head's
// limits.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "marker/job/job_checks.hpp"
#include "tests/marker/plan_test_support.hpp"

namespace mark {
namespace {

JobSpec spec_for(const std::string& text, CornerStrategy corner = CornerStrategy::blanking,
                 double speed = 800) {
  JobSpec spec;
  spec.text = text;
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 2;
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, corner, speed);
  return spec;
}

// The message of the InputError the call throws ("" if none).
template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "one line";
    return m;
  }
  return "";
}

TEST(JobRefusal, EmptyTextAndTextWithNothingToMark) {
  EXPECT_NE(refusal([] { compile_job(spec_for("")); }).find("text to mark is empty"),
            std::string::npos);
  EXPECT_NE(refusal([] { compile_job(spec_for("   ")); }).find("nothing to mark"),
            std::string::npos);
}

TEST(JobRefusal, SpeedOutsideTheHeadsLimits) {
  for (double v : {0.0, -5.0, 25000.0, std::numeric_limits<double>::quiet_NaN()}) {
    const std::string m = refusal([&] { compile_job(spec_for("A", CornerStrategy::blanking, v)); });
    EXPECT_NE(m.find("marking speed"), std::string::npos) << v;
    EXPECT_NE(m.find("SL10"), std::string::npos) << m;
  }
  JobSpec s = spec_for("A");
  s.pen.jump_speed_mm_s = 30000;
  EXPECT_NE(refusal([&] { compile_job(s); }).find("jump speed 30000.0 mm/s"), std::string::npos);
}

TEST(JobRefusal, TickOutsideTheHeadsLimits) {
  for (double tick : {50e-6, 0.5e-6, 0.0}) {
    JobSpec s = spec_for("A");
    s.pen.tick_s = tick;
    const std::string m = refusal([&] { compile_job(s); });
    EXPECT_NE(m.find("tick"), std::string::npos) << tick;
    EXPECT_NE(m.find("24.0 µs"), std::string::npos) << m;  // 20 % of τ = 0.12 ms
  }
  JobSpec ok = spec_for("A");
  ok.pen.tick_s = 20e-6;
  EXPECT_EQ(refusal([&] { compile_job(ok); }), "");
}

// A horizontal stroke ending 0.1 mm inside the field's right edge: the figure fits, but its
// blanking run-out (v·τ = 0.24 mm at 2 m/s) would leave the field — refused; the same figure
// without blanking lines is accepted.
TEST(JobRefusal, BlankingLinesLeavingTheFieldAreRefused) {
  const Figure f = test::figure_of({{Element::line({50, 0}, {54.9, 0})}});
  const HeadModel head = head_sl10();
  const Plan blank = plan_figure(f, pen_for_head(head, CornerStrategy::blanking, 2000));
  ASSERT_GT(blank.bounds().max.x(), 55.0);
  const std::string m = refusal([&] { check_plan(blank, head); });
  EXPECT_NE(m.find("figure plus blanking lines"), std::string::npos) << m;
  EXPECT_NE(m.find("leaves the field"), std::string::npos) << m;
  EXPECT_EQ(refusal([&] { check_plan(plan_figure(f, pen_for_head(head, CornerStrategy::none, 2000)),
                                     head); }),
            "");
}

TEST(JobRefusal, TextNearTheEdgeRefusedBeforeTheFirstSample) {
  JobSpec s = spec_for("EDGE");
  s.layout.align = Align::right;
  s.layout.base = Point(54.95, 0);  // the letters end just inside the field
  ASSERT_LT(layout_text(s.text, *s.font, s.layout).bounds().max.x(), 55.0);  // the text fits
  SimScanner sim(simulator_options(s));
  JobOptions options;
  options.virtual_time = true;
  const std::string m = refusal([&] { run_job(s, options, sim); });
  EXPECT_NE(m.find("figure plus blanking lines"), std::string::npos) << m;
  EXPECT_NE(m.find("leaves the field"), std::string::npos) << m;
  EXPECT_EQ(sim.samples(), 0u);  // the device never saw a sample
  EXPECT_EQ(sim.status().state, DeviceState::idle);  // nor was a job begun on it
}

}  // namespace
}  // namespace mark
