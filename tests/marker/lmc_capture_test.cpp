// A real job (layout, plan, the runner's device program, LmcDevice) captured instead of sent:
// every lit MarkTo's end point lies on the intended strokes within the chord tolerance (plus
// the board's one-unit truncation), and the whole lit segment between two of them within the
// chord tolerance of the curve; the CLI's --device lmc-capture and `marker frame` write the
// same kind of file; malformed --device values are refused with the forms allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "driver/lmc/capture_link.hpp"
#include "driver/lmc/job_encoder.hpp"
#include "driver/lmc/lmc_device.hpp"
#include "fonts/catalog.hpp"
#include "marker/job/device_program.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job.hpp"
#include "tests/marker/cli_runner.hpp"
#include "tests/marker/polyline_distance.hpp"

namespace mark {
namespace {

using test::distance_to;

TEST(LmcCapture, LitMarkEndPointsLieOnTheIntendedStrokes) {
  const auto path = test::fresh_temp_file("lmc_capture_test", "serial.lmc");
  JobSpec spec;
  spec.text = "SN 0815-B";  // arcs in S, 0, 8, 5 and B: they arrive as chords
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 3;
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, CornerStrategy::blanking, 1000);
  lmc::LmcOptions o;
  o.init.settle_s = 0;
  JobResult r;
  {
    lmc::LmcDevice device(std::make_unique<lmc::CaptureLink>(path.string()), o);
    r = run_job(spec, JobOptions{}, device);
    ASSERT_EQ(r.outcome, JobOutcome::done);
  }
  const double tol = o.chord_tolerance_mm;
  const lmc::FieldUnits units(o.field_mm, o.axes, o.polygon_delay_unit);
  const double unit_mm = std::sqrt(2.0) / units.units_per_mm();  // truncation of both words
  const auto intended = intended_polylines(r.job.figure, 0.002);

  std::array<std::uint16_t, 2> at{0x8000, 0x8000};
  std::size_t marks = 0, packets = 0;
  double worst_end = 0, worst_mid = 0;
  for (const lmc::CaptureRecord& rec : lmc::read_capture(path.string())) {
    if (!rec.packet) continue;
    ++packets;
    for (const lmc::Word& w : rec.words) {
      const auto op = static_cast<lmc::Op>(w.opcode());
      if (op != lmc::Op::MarkTo && op != lmc::Op::JumpTo) continue;
      const std::array<std::uint16_t, 2> to{w.p(1), w.p(2)};
      if (op == lmc::Op::MarkTo) {
        ++marks;
        const auto p = units.field_point(to[0], to[1]);
        const auto q = units.field_point(at[0], at[1]);
        worst_end = std::max(worst_end, distance_to(intended, {p[0], p[1]}));
        // The chord's middle: how far the straight lit segment strays from the curve.
        worst_mid = std::max(worst_mid, distance_to(intended, {(p[0] + q[0]) / 2, (p[1] + q[1]) / 2}));
      }
      at = to;
    }
  }
  double reported_packets = -1;
  for (const auto& [k, v] : r.device.figures)
    if (k == "packets") reported_packets = v;
  EXPECT_EQ(double(packets), reported_packets);
  EXPECT_GT(marks, 100u);
  EXPECT_LE(worst_end, tol) << "a lit end point " << worst_end * 1e3 << " µm off the strokes";
  EXPECT_LE(worst_end, unit_mm + 1e-4);  // in fact: only the truncation
  EXPECT_LE(worst_mid, tol + unit_mm) << "a chord " << worst_mid * 1e3 << " µm off the curve";
  std::printf("%zu lit MarkTo: end points within %.2f µm, chord middles within %.2f µm "
              "(tolerance %.1f µm)\n",
              marks, worst_end * 1e3, worst_mid * 1e3, tol * 1e3);
}

// What a job's list costs now that every list sets every setting, and what it saved that a pen
// keeps one MarkSpeed: the same job as the host planned it before (blanking at whole-tick
// speeds, stroke by stroke), encoded by the same encoder, counted word by word.
TEST(LmcCapture, OneMarkSpeedPerPenAndEverySettingInThePreamble) {
  JobSpec spec;
  spec.text = "SN 0815-B";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 3;
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, CornerStrategy::blanking, 1000);
  const lmc::LmcOptions o;
  const lmc::FieldUnits units(o.field_mm, o.axes, o.polygon_delay_unit);
  DeviceDescription desc;
  desc.level = DeviceLevel::commands;
  desc.field_mm = o.field_mm;
  desc.chord_tolerance_mm = o.chord_tolerance_mm;
  const Figure figure = job_figure(spec);
  struct Count {
    std::size_t words = 0, parameters = 0, mark_speeds = 0, jump_delays = 0;
    std::set<std::uint16_t> mark_speed_values;
  };
  const auto count = [&](const Plan& plan) {
    const DeviceProgram program = device_program(plan, spec.laser, desc);
    Count c;
    lmc::JobEncoder enc(units, [&](const lmc::ListPacket& p, const lmc::PacketInfo&) {
      for (std::size_t i = 0; i < p.used(); ++i) {
        const lmc::Word w = lmc::load(p.bytes().data() + 12 * i);
        ++c.words;
        if (w.opcode() == std::uint16_t(lmc::Op::MarkSpeed)) {
          ++c.mark_speeds;
          c.mark_speed_values.insert(w.p(1));
        }
        c.jump_delays += w.opcode() == std::uint16_t(lmc::Op::JumpDelay);
      }
    });
    const std::vector<lmc::BoardPen> pens{lmc::encode_pen(program.pen, 0, units)};
    enc.start_list(o.open_mo_delay_s, 1);
    enc.apply_pen(pens[0]);
    enc.add(program.commands, 0, pens);
    enc.finish(program.commands.size());
    c.parameters = enc.figures().parameter_commands;
    return c;
  };
  const Count now = count(plan_for_device(figure, spec.pen, spec.order));
  Pen whole_ticks = spec.pen;  // the plan as it was made for a board before
  Plan before = plan_figure(figure, whole_ticks, spec.order);
  const Count was = count(before);
  std::printf("SN 0815-B, one list: %zu words (%zu parameters, %zu MarkSpeed with %zu values, %zu JumpDelay) "
              "against %zu words (%zu parameters, %zu MarkSpeed with %zu values) with whole-tick speeds\n",
              now.words, now.parameters, now.mark_speeds, now.mark_speed_values.size(), now.jump_delays, was.words,
              was.parameters, was.mark_speeds, was.mark_speed_values.size());
  EXPECT_EQ(now.mark_speeds, 1u);  // the preamble's: one pen, one speed
  EXPECT_GE(was.mark_speed_values.size(), 2u);  // the speed words alternated (595 / 596 …)
  EXPECT_GT(was.mark_speeds, 1u);
  EXPECT_GE(now.jump_delays, 1u);  // the preamble's, whatever the pen's jump delay
}

TEST(LmcCapture, MarkAndFrameOnTheCommandLine) {
  const auto file = test::fresh_temp_file("lmc_capture_test", "cli.lmc");
  const auto r = test::run_cli({"mark", "SN 42", "--height", "2", "--device",
                                "lmc-capture:" + file.string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "done");
  EXPECT_EQ(j["device"], "lmc 00000000");
  const auto& f = j["device_figures"];
  EXPECT_GT(f["commands"].get<double>(), 10);
  EXPECT_EQ(f["packets"].get<double>(), 1);
  EXPECT_GT(f["list_commands_per_packet"].get<double>(), 10);
  std::size_t lists = 0;
  for (const auto& rec : lmc::read_capture(file.string())) lists += rec.packet;
  EXPECT_EQ(lists, 1u);

  const auto frame = test::fresh_temp_file("lmc_capture_test", "frame.lmc");
  const auto fr = test::run_cli({"frame", "SN 42", "--height", "2", "--device",
                                 "lmc-capture:" + frame.string(), "--laps", "3", "--json"});
  ASSERT_EQ(fr.code, 0) << fr.err;
  const auto fj = nlohmann::json::parse(fr.out);
  EXPECT_EQ(fj["laps"], 3);
  EXPECT_EQ(fj["stopped"], false);
  bool red_on = false, laser_bit = false, marks = false;
  for (const auto& rec : lmc::read_capture(frame.string()))
    for (const lmc::Word& w : rec.words) {
      const auto op = static_cast<lmc::Op>(w.opcode());
      if (op == lmc::Op::WritePort || op == lmc::Op::ListWritePort) {
        red_on |= (w.p(1) & 0x100) != 0;
        laser_bit |= (w.p(1) & 1) != 0;
      }
      marks |= op == lmc::Op::MarkTo;
    }
  EXPECT_TRUE(red_on);
  EXPECT_FALSE(laser_bit);
  EXPECT_FALSE(marks);
}

TEST(LmcCapture, MalformedDevicesAreRefused) {
  auto r = test::run_cli({"mark", "A", "--device", "lmc:xyz"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--device 'lmc:xyz': a board serial is 1 to 8 hex digits"), std::string::npos) << r.err;
  r = test::run_cli({"mark", "A", "--device", "lmc-capture:"});
  EXPECT_NE(r.err.find("no file"), std::string::npos) << r.err;
  r = test::run_cli({"frame", "A", "--device", "sim"});
  EXPECT_NE(r.err.find("framing needs an LMC board"), std::string::npos) << r.err;
  const auto file = test::fresh_temp_file("lmc_capture_test", "endless.lmc");
  r = test::run_cli({"frame", "A", "--device", "lmc-capture:" + file.string()});
  EXPECT_NE(r.err.find("give --laps"), std::string::npos) << r.err;
  r = test::run_cli({"mark", "A", "--device", "lmc-capture:" + file.string(), "--power", "120"});
  EXPECT_NE(r.err.find("--power: 120 is outside the range 0 to 100 %"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace mark
