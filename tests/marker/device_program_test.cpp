// The plan as a command-level board takes it: lit arcs and ellipse arcs as chords within the
// device's tolerance, blanking lines as jumps at their planned speed, the delays strategy's
// delays as board parameters instead of host dwells, every point checked against the device's
// field before begin_job; and the job runner's command path (done, stop, fault, ink marked).
#include "marker/job/device_program.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <thread>
#include <numbers>

#include "base/error.hpp"
#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/job/program_stream.hpp"
#include "tests/marker/plan_test_support.hpp"
#include "tests/marker/recording_command_device.hpp"

namespace mark {
namespace {

using test::RecordingCommandDevice;

DeviceDescription board(double tol = 0.005, double field = 110) {
  DeviceDescription d = RecordingCommandDevice().describe();
  d.chord_tolerance_mm = tol;
  d.field_mm = field;
  return d;
}

// Largest distance of the circle (centre c, radius r) from the chords between consecutive
// points: at each chord's middle the arc bulges by r − |midpoint − c|.
double worst_sagitta(const std::vector<Point>& pts, const Point& c, double r) {
  double worst = 0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    worst = std::max(worst, r - ((pts[i] + pts[i - 1]) / 2 - c).norm());
  return worst;
}

std::vector<Point> marked_points(const DeviceProgram& p, Point start) {
  std::vector<Point> pts{start};
  for (const DeviceCommand& c : p.commands)
    if (c.op == DeviceOp::mark) pts.emplace_back(c.x_mm, c.y_mm);
  return pts;
}

TEST(DeviceProgram, ArcsBecomeChordsWithinTheTolerance) {
  const Pen pen = pen_for_head(head_sl10(), CornerStrategy::none, 1000);
  for (double r : {0.05, 0.4, 2.0, 20.0}) {
    for (double tol : {0.001, 0.005, 0.02}) {
      const Element arc = Element::arc({1, 1}, r, 0.3, 1.5 * std::numbers::pi);
      const Plan plan = plan_figure(test::figure_of({{arc}}), pen);
      const DeviceProgram p = device_program(plan, {}, board(tol));
      const std::vector<Point> pts = marked_points(p, arc.start());
      for (const Point& q : pts) EXPECT_NEAR((q - Point(1, 1)).norm(), r, 1e-9);  // on the arc
      EXPECT_LE(worst_sagitta(pts, {1, 1}, r), tol * (1 + 1e-9)) << "r " << r << " tol " << tol;
      // Not wastefully many: within a factor 1.5 of the fewest chords that meet the tolerance.
      const double fewest = std::ceil(1.5 * std::numbers::pi / (2 * std::acos(1 - std::min(tol / r, 1.0))));
      EXPECT_LE(static_cast<double>(p.chords), 1.5 * fewest + 1) << "r " << r << " tol " << tol;
      EXPECT_NEAR(lit_length_mm(p), arc.length(), arc.length() * 1e-3 + 2 * tol);
    }
  }
}

TEST(DeviceProgram, EllipseArcsBecomeChordsOnTheEllipse) {
  const Pen pen = pen_for_head(head_sl10(), CornerStrategy::none, 1000);
  const Element e = Element::ellipse({0, 0}, 3, 1, 0.4, 0, 2 * std::numbers::pi);
  const Plan plan = plan_figure(test::figure_of({{e}}), pen);
  const DeviceProgram p = device_program(plan, {}, board(0.005));
  const std::vector<Point> pts = marked_points(p, e.start());
  // Each chord's middle lies within the tolerance of the ellipse: check against a dense
  // sampling of the ellipse.
  std::vector<Point> dense;
  for (int k = 0; k <= 20000; ++k) dense.push_back(e.point_at(k / 20000.0));
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const Point mid = (pts[i] + pts[i - 1]) / 2;
    double d = 1e9;
    for (const Point& q : dense) d = std::min(d, (q - mid).norm());
    ASSERT_LE(d, 0.005 + 1e-4) << "chord " << i;
  }
}

TEST(DeviceProgram, DelaysGoToTheBoardNotIntoThePlan) {
  JobSpec spec;
  spec.text = "HI";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 3;
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, CornerStrategy::delays, 800);
  const CompiledJob host = compile_job(spec, DeviceLevel::samples);
  const CompiledJob dev = compile_job(spec, DeviceLevel::commands);
  ASSERT_GT(host.plan.count(CommandRole::delay), 0u);  // the host plan waits itself
  EXPECT_EQ(dev.plan.count(CommandRole::delay), 0u);   // the board's plan does not
  const DeviceProgram p = device_program(dev.plan, {60, 25, 200}, board());
  for (const DeviceCommand& c : p.commands) EXPECT_NE(c.op, DeviceOp::dwell);
  EXPECT_DOUBLE_EQ(p.pen.jump_delay_s, spec.pen.jump_delay_s);
  EXPECT_DOUBLE_EQ(p.pen.polygon_delay_s, spec.pen.polygon_delay_s);
  EXPECT_DOUBLE_EQ(p.pen.laser_on_delay_s, spec.pen.laser_on_delay_s);
  EXPECT_DOUBLE_EQ(p.pen.laser_off_delay_s, spec.pen.laser_off_delay_s);
  EXPECT_GE(p.pen.mark_delay_s, spec.pen.laser_off_delay_s);
  EXPECT_DOUBLE_EQ(p.pen.laser.power_pct, 60);
  EXPECT_DOUBLE_EQ(p.pen.laser.frequency_khz, 25);
  EXPECT_DOUBLE_EQ(p.pen.laser.pulse_width_ns, 200);
  // Sample-level devices get the laser settings only: the host applies the delays.
  const DevicePen s = device_pen(spec.pen, {60, 25, 200}, DeviceLevel::samples);
  EXPECT_EQ(s.jump_delay_s, 0.0);
  EXPECT_EQ(s.laser_on_delay_s, 0.0);
}

TEST(DeviceProgram, BlankingLinesAreJumpsAtTheirPlannedSpeed) {
  const Pen pen = pen_for_head(head_sl10(), CornerStrategy::blanking, 1000);
  const Figure f = test::figure_of({{Element::line({0, 0}, {2, 0}), Element::line({2, 0}, {2, 2})}});
  const Plan plan = plan_figure(f, pen);
  const DeviceProgram p = device_program(plan, {}, board());
  std::size_t at_speed = 0, plain = 0, marks = 0;
  for (const DeviceCommand& c : p.commands) {
    if (c.op == DeviceOp::jump) (c.speed_mm_s > 0 ? at_speed : plain)++;
    if (c.op == DeviceOp::mark) ++marks;
  }
  EXPECT_EQ(marks, 2u);
  EXPECT_EQ(plain, 1u);  // home → the first run-in
  // run-in, run-out, join, run-in, run-out: laser-off lines at their planned speed.
  EXPECT_EQ(at_speed, plan.count(CommandRole::run_in) + plan.count(CommandRole::run_out) +
                          plan.count(CommandRole::blank_join));
  EXPECT_EQ(p.pen.jump_delay_s, 0.0);  // nothing waits between a run-in and its stroke
  EXPECT_DOUBLE_EQ(p.pen.laser_on_delay_s, pen.laser_on_delay_s);
}

TEST(DeviceProgram, PointOutsideTheDeviceFieldIsRefusedBeforeTheJob) {
  JobSpec spec;
  spec.text = "FIELD";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 4;
  spec.layout.base = Point(2, 0);  // the text reaches x ≈ 14 mm
  spec.head = head_sl10();
  spec.head.field_mm = 30;
  spec.pen = pen_for_head(spec.head, CornerStrategy::none, 800);
  RecordingCommandDevice dev;
  dev.description.field_mm = 30;
  JobSpec wide = spec;
  wide.head.field_mm = 110;
  EXPECT_THROW(run_job(wide, JobOptions{}, dev), InputError);  // job field larger than the board's
  const CompiledJob job = compile_job(spec, DeviceLevel::commands);
  DeviceDescription small = board(0.005, 40);
  small.field_mm = 40;
  EXPECT_NO_THROW(device_program(job.plan, {}, small));
  small.field_mm = 20;
  try {
    device_program(job.plan, {}, small);
    FAIL() << "a point outside a 20 mm field was accepted";
  } catch (const DeviceFaultError& e) {
    EXPECT_EQ(e.fault().category, FaultCategory::out_of_field);
    EXPECT_NE(std::string(e.what()).find("outside the field ±10.000 mm"), std::string::npos) << e.what();
  }
}

JobSpec board_job() {
  JobSpec spec;
  spec.text = "SN 0042";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 3;
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, CornerStrategy::blanking, 1000);
  spec.laser = {80, 30, 0};
  return spec;
}

// Ink is walked on demand from the commands: it starts at 0, ends at 1, never falls, grows
// only over lit commands, and the program's lit length is the plan's stroke length to within
// the chords' shortening.
TEST(DeviceProgram, InkGrowsOverLitCommandsOnly) {
  const JobSpec spec = board_job();
  const CompiledJob job = compile_job(spec, DeviceLevel::commands);
  const DeviceProgram p = device_program(job.plan, spec.laser, board());
  double strokes = 0;
  for (const Command& c : job.plan.commands)
    if (c.role == CommandRole::stroke) strokes += c.length;
  EXPECT_NEAR(lit_length_mm(p), strokes, strokes * 1e-3);
  EXPECT_EQ(ink_fraction(p, 0), 0.0);
  EXPECT_DOUBLE_EQ(ink_fraction(p, p.commands.size()), 1.0);
  double before = 0;
  for (std::size_t k = 1; k <= p.commands.size(); ++k) {
    const double f = ink_fraction(p, k);
    if (p.commands[k - 1].op == DeviceOp::mark) {
      EXPECT_GE(f, before) << "command " << k - 1;
    } else {
      EXPECT_EQ(f, before) << "command " << k - 1 << " is not lit";
    }
    before = f;
  }
}

TEST(DeviceProgram, JobRunsOnACommandDevice) {
  RecordingCommandDevice dev;
  const JobResult r = run_job(board_job(), JobOptions{}, dev);
  EXPECT_EQ(r.outcome, JobOutcome::done);
  ASSERT_EQ(dev.headers.size(), 1u);
  EXPECT_DOUBLE_EQ(dev.headers[0].pens.at(0).laser.power_pct, 80);
  EXPECT_EQ(dev.received.front().op, DeviceOp::pen);
  EXPECT_EQ(r.device.commands_done, dev.received.size());
  EXPECT_EQ(r.commands, dev.received.size());
  // Again on the same device: re-armed, same commands.
  const std::size_t first = dev.received.size();
  dev.received.clear();
  EXPECT_EQ(run_job(board_job(), JobOptions{}, dev).outcome, JobOutcome::done);
  EXPECT_EQ(dev.received.size(), first);
}

TEST(DeviceProgram, InjectedAbortStopsTheBoardAtTheCommand) {
  RecordingCommandDevice dev;
  JobOptions o;
  o.inject = {Injection::Kind::abort, 40};
  const JobResult r = run_job(board_job(), o, dev);
  EXPECT_EQ(r.outcome, JobOutcome::aborted);
  EXPECT_EQ(dev.received.size(), 40u);
  EXPECT_EQ(r.stopped_at, 40u);
  EXPECT_GT(r.ink_marked, 0.0);
  EXPECT_LT(r.ink_marked, 1.0);
  EXPECT_GE(dev.aborts.load(), 1);
  // An underrun is a drain's fault: a board runs its own clock.
  o.inject = {Injection::Kind::underrun, 40};
  EXPECT_THROW(run_job(board_job(), o, dev), InputError);
}

TEST(DeviceProgram, TransportFaultIsReportedWithWhatWasMarked) {
  RecordingCommandDevice dev;
  dev.fail_at = 25;
  const JobResult r = run_job(board_job(), JobOptions{}, dev);
  EXPECT_EQ(r.outcome, JobOutcome::failed);
  ASSERT_TRUE(r.fault);
  EXPECT_EQ(r.fault->category, FaultCategory::transport);
  EXPECT_EQ(r.stopped_at, 25u);
  const DeviceProgram p = device_program(r.job.plan, board_job().laser, dev.describe());
  EXPECT_DOUBLE_EQ(r.ink_marked, ink_fraction(p, 25));
}

// An error that is not a device fault (a bug, memory) escapes the job, but only after the board
// was told to stop: it is not left running the commands it already has, laser and all.
TEST(DeviceProgram, AnErrorThatIsNotAFaultStopsTheBoardBeforeItEscapes) {
  RecordingCommandDevice dev;
  dev.error_at = 25;
  EXPECT_THROW(run_job(board_job(), JobOptions{}, dev), std::runtime_error);
  EXPECT_EQ(dev.received.size(), 25u);
  EXPECT_GE(dev.aborts.load(), 1);
  EXPECT_EQ(dev.status().state, DeviceState::aborted);
}

// Rows of the 62 characters at 1 mm: ten of them are a plan of thousands of commands, above
// the stream's threshold.
JobSpec rows_job(int rows) {
  JobSpec spec = board_job();
  std::string text;
  for (int r = 0; r < rows; ++r)
    text += (r ? "\n" : "") + std::string("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789");
  spec.text = text;
  spec.layout.height_mm = 1;
  spec.layout.align = Align::center;
  spec.layout.base = Point(0, 0.75 * rows);
  return spec;
}

// Field by field, exactly: the stream must hand out the very commands the whole conversion makes.
void expect_same_commands(std::span<const DeviceCommand> got, std::span<const DeviceCommand> want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    const DeviceCommand& a = got[i];
    const DeviceCommand& b = want[i];
    ASSERT_TRUE(a.op == b.op && a.laser == b.laser && a.pen == b.pen && a.x_mm == b.x_mm &&
                a.y_mm == b.y_mm && a.cx_mm == b.cx_mm && a.cy_mm == b.cy_mm &&
                a.sweep_rad == b.sweep_rad && a.speed_mm_s == b.speed_mm_s && a.dwell_s == b.dwell_s)
        << "command " << i;
  }
}

std::vector<DeviceCommand> drain(ProgramStream& s, std::size_t max) {
  std::vector<DeviceCommand> got;
  for (auto c = s.next(0, max); !c.empty(); c = s.next(got.size(), max)) {
    EXPECT_LE(c.size(), max);
    got.insert(got.end(), c.begin(), c.end());
  }
  return got;
}

TEST(DeviceProgram, StreamHandsOutTheWholeConversionsCommands) {
  const JobSpec spec = rows_job(10);
  const CompiledJob job = compile_job(spec, DeviceLevel::commands);
  ASSERT_GE(job.plan.commands.size(), kStreamMinPlanCommands);
  const DeviceProgram whole = device_program(job.plan, spec.laser, board());
  ASSERT_GT(whole.chords, 1000u);
  const bool cores = std::thread::hardware_concurrency() >= 2;
  for (StreamMode mode : {StreamMode::automatic, StreamMode::worker, StreamMode::whole}) {
    for (std::size_t max : {1, 7, 256, 1 << 20}) {
      ProgramStream s(job.plan, spec.laser, board(), mode);
      EXPECT_EQ(s.streaming(), mode == StreamMode::worker || (mode == StreamMode::automatic && cores));
      EXPECT_DOUBLE_EQ(s.pen().laser.power_pct, 80);
      const std::vector<DeviceCommand> got = drain(s, max);
      expect_same_commands(got, whole.commands);
      EXPECT_TRUE(s.next(got.size(), max).empty());
      EXPECT_TRUE(s.next(got.size() + 5, max).empty());
      const DeviceProgram p = s.finish();
      expect_same_commands(p.commands, whole.commands);
      EXPECT_EQ(p.chords, whole.chords);
      EXPECT_EQ(p.pen.laser_on_delay_s, whole.pen.laser_on_delay_s);
    }
  }
}

// A plan whose reach (an arc's whole circle) crosses the field edge while its points do not is
// converted whole before anything is handed out; one with a point outside the field is refused
// by the constructor with device_program's message, whether or not it is big; so is a NaN.
TEST(DeviceProgram, StreamConvertsWholeFirstWhatMayLeaveTheField) {
  const Pen pen = pen_for_head(head_sl10(), CornerStrategy::none, 1000);
  // The left half of a circle of radius 5 around (10, 0): x from 5 to 10, the circle to 15.
  const Element arc = Element::arc({10, 0}, 5, std::numbers::pi / 2, std::numbers::pi);
  const Plan plan = plan_figure(test::figure_of({{arc}}), pen);
  const DeviceProgram whole = device_program(plan, {}, board(0.005, 22));
  ProgramStream s(plan, {}, board(0.005, 22), StreamMode::worker);
  EXPECT_FALSE(s.streaming());
  expect_same_commands(drain(s, 256), whole.commands);
  ProgramStream inside(plan, {}, board(0.005, 40), StreamMode::worker);
  EXPECT_TRUE(inside.streaming());
  expect_same_commands(drain(inside, 256), whole.commands);

  const auto refusal = [](auto&& make) -> std::string {
    try {
      make();
    } catch (const DeviceFaultError& e) {
      EXPECT_EQ(e.fault().category, FaultCategory::out_of_field);
      return e.what();
    }
    ADD_FAILURE() << "accepted";
    return "";
  };
  for (StreamMode mode : {StreamMode::worker, StreamMode::whole}) {
    const std::string want = refusal([&] { device_program(plan, {}, board(0.005, 16)); });
    EXPECT_NE(want.find("outside the field ±8.000 mm"), std::string::npos) << want;
    EXPECT_EQ(refusal([&] { ProgramStream(plan, {}, board(0.005, 16), mode); }), want);
  }
  const JobSpec big = rows_job(10);
  const CompiledJob job = compile_job(big, DeviceLevel::commands);
  const std::string want = refusal([&] { device_program(job.plan, {}, board(0.005, 30)); });
  EXPECT_EQ(refusal([&] { ProgramStream(job.plan, {}, board(0.005, 30)); }), want);

  Plan bad;
  bad.pen = pen;
  bad.commands.push_back(Command::jump({0, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}, 0));
  EXPECT_NE(refusal([&] { ProgramStream(bad, {}, board(), StreamMode::worker); }).find("nan"),
            std::string::npos);
}

// The runner submits a big job while it is converted: the board gets exactly the whole
// conversion's commands, in order; an injected abort stops it at the command with the ink of
// the commands before it.
TEST(DeviceProgram, BigJobStreamsToTheBoardInOrder) {
  const JobSpec spec = rows_job(10);
  RecordingCommandDevice dev;
  const JobResult r = run_job(spec, JobOptions{}, dev);
  EXPECT_EQ(r.outcome, JobOutcome::done);
  const DeviceProgram whole = device_program(r.job.plan, spec.laser, dev.describe());
  expect_same_commands(dev.received, whole.commands);
  EXPECT_EQ(r.commands, whole.commands.size());

  RecordingCommandDevice stopped;
  JobOptions o;
  o.inject = {Injection::Kind::abort, 5000};
  const JobResult a = run_job(spec, o, stopped);
  EXPECT_EQ(a.outcome, JobOutcome::aborted);
  EXPECT_EQ(stopped.received.size(), 5000u);
  EXPECT_EQ(a.stopped_at, 5000u);
  EXPECT_DOUBLE_EQ(a.ink_marked, ink_fraction(whole, 5000));
}

TEST(DeviceProgram, StopRequestBeforeTheJobAbortsTheBoard) {
  RecordingCommandDevice dev;
  StopFlag stop;
  stop.request();
  JobOptions o;
  o.stop = &stop;
  const JobResult r = run_job(board_job(), o, dev);
  EXPECT_EQ(r.outcome, JobOutcome::aborted);
  EXPECT_EQ(dev.received.size(), 0u);
  EXPECT_EQ(r.ink_marked, 0.0);
}

}  // namespace
}  // namespace mark
