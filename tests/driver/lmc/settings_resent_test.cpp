// Every list carries every setting its marks depend on: the same job marks the same — tick for
// tick, from its first lit tick on — after an aborted job whose packet never left the host,
// after a job with other pens, and on a board that starts with registers another program left.
// The emulated board's lit_stream_hash compares the output (position, gate, power of every
// tick). Before every preamble carried JumpDelay, the aborted-job and foreign-settings cases
// differed (the encoder took an unsent JumpDelay, or a fresh board's, as on the board); the
// other-pens case held then too and is kept so it stays so.
#include <gtest/gtest.h>

#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc {
namespace {

// A blanking-style job: travel jumps, run-ins and run-outs as JumpTo at marking speed (jump
// delay 0 matters: a held delay stops the mirrors between run-in and stroke), strokes with a
// corner.
std::vector<DeviceCommand> blanking_job() {
  std::vector<DeviceCommand> c;
  for (int k = 0; k < 12; ++k) {
    const double x = -10 + 1.5 * k, y = (k % 3) * 1.2;
    c.push_back(DeviceCommand::jump_to(x - 0.3, y));
    c.push_back(DeviceCommand::jump_to(x, y, 800));  // run-in
    c.push_back(DeviceCommand::mark_to(x + 1, y));
    c.push_back(DeviceCommand::mark_to(x + 1, y + 1));
    c.push_back(DeviceCommand::jump_to(x + 1, y + 1.3, 800));  // run-out
  }
  return c;
}

// A delays-style job: marks and travel jumps only, so the board is left holding its pen's jump
// delay (a blanking line would set 0 on its way).
std::vector<DeviceCommand> delays_job() {
  std::vector<DeviceCommand> c;
  for (int k = 0; k < 6; ++k) {
    c.push_back(DeviceCommand::jump_to(-8 + 2.0 * k, -3));
    c.push_back(DeviceCommand::mark_to(-7 + 2.0 * k, -3));
    c.push_back(DeviceCommand::mark_to(-7 + 2.0 * k, -2));
  }
  c.push_back(DeviceCommand::jump_to(4, 4));
  return c;
}

DevicePen blanking_pen() {
  DevicePen p;
  p.mark_speed_mm_s = 800;
  p.jump_speed_mm_s = 3000;
  p.laser_on_delay_s = 100e-6;
  p.laser_off_delay_s = 120e-6;
  p.laser.power_pct = 70;
  p.laser.frequency_khz = 40;
  return p;
}

// Another pen with every setting different.
DevicePen other_pen() {
  DevicePen p;
  p.mark_speed_mm_s = 300;
  p.jump_speed_mm_s = 1500;
  p.laser_on_delay_s = 40e-6;
  p.laser_off_delay_s = 250e-6;
  p.jump_delay_s = 200e-6;
  p.mark_delay_s = 300e-6;
  p.polygon_delay_s = 150e-6;
  p.laser.power_pct = 30;
  p.laser.frequency_khz = 25;
  return p;
}

struct Marked {
  std::uint64_t hash = 0;
  std::uint64_t lit_ticks = 0;
};

Marked run(test::LoopbackBench& bench, const JobHeader& header, const std::vector<DeviceCommand>& cmds) {
  const std::uint64_t lit_before = bench.board.state().executor.lit_ticks;
  LmcDevice& dev = *bench.device;
  if (dev.status().state != DeviceState::idle) dev.reset();
  dev.begin_job(header);
  dev.submit(cmds);
  const DeviceReport r = dev.end_job();
  EXPECT_EQ(r.outcome, DeviceState::done) << (r.fault ? r.fault->message : "");
  const BoardState s = bench.board.state();
  EXPECT_TRUE(bench.board.violations().empty());
  return {s.executor.lit_stream_hash, s.executor.lit_ticks - lit_before};
}

constexpr double kScale = 20;  // board clock × wall clock: these compare output, not timing

Marked on_a_fresh_board() {
  test::LoopbackBench bench({}, {}, test::quick_options(), kScale);
  return run(bench, test::header_with(blanking_pen()), blanking_job());
}

TEST(LmcSettingsResent, AfterAnAbortedJobWhosePacketNeverWentOut) {
  const Marked fresh = on_a_fresh_board();
  ASSERT_GT(fresh.lit_ticks, 1000u);
  test::LoopbackBench bench({}, {}, test::quick_options(), kScale);
  // Job 0 leaves the board with the other pen's registers (jump delay 200 µs, ...).
  run(bench, test::header_with(other_pen()), delays_job());
  // Job 1 with the blanking pen: its preamble (JumpDelay 0, ...) is encoded, but the job is
  // aborted before its first packet goes out.
  LmcDevice& dev = *bench.device;
  dev.reset();
  dev.begin_job(test::header_with(blanking_pen()));
  const std::size_t packets = bench.board.state().packets_received;
  dev.abort();
  dev.end_job();
  EXPECT_EQ(bench.board.state().packets_received, packets + 1);  // only the stop's flush list
  // Job 2, the same pen: it must set everything again.
  const Marked again = run(bench, test::header_with(blanking_pen()), blanking_job());
  EXPECT_EQ(again.hash, fresh.hash);
  EXPECT_EQ(again.lit_ticks, fresh.lit_ticks);
}

TEST(LmcSettingsResent, AfterAJobWithOtherPens) {
  const Marked fresh = on_a_fresh_board();
  test::LoopbackBench bench({}, {}, test::quick_options(), kScale);
  JobHeader two = test::header_with(blanking_pen());
  two.pens.push_back(other_pen());
  std::vector<DeviceCommand> cmds = blanking_job();
  cmds.push_back(DeviceCommand::select_pen(1));  // the job ends on pen 1: jump delay 200 µs, ...
  for (const DeviceCommand& c : delays_job()) cmds.push_back(c);
  run(bench, two, cmds);
  const Marked again = run(bench, test::header_with(blanking_pen()), blanking_job());
  EXPECT_EQ(again.hash, fresh.hash);
}

TEST(LmcSettingsResent, OnABoardThatStartsWithForeignSettings) {
  const Marked fresh = on_a_fresh_board();
  test::LoopbackBench bench(with_variant({}, "foreign_settings"), {}, test::quick_options(), kScale);
  const Marked foreign = run(bench, test::header_with(blanking_pen()), blanking_job());
  EXPECT_EQ(foreign.hash, fresh.hash);
  EXPECT_EQ(foreign.lit_ticks, fresh.lit_ticks);
  // The red-pointer frame, too: its jumps at the red-light speed with no jump delay.
  const std::vector<std::vector<Vec2>> box{{{-5, -2}, {5, -2}, {5, 2}, {-5, 2}, {-5, -2}}};
  test::LoopbackBench clean({}, {}, test::quick_options(), kScale);
  // One lap to bring both boards' mirrors to the box, then five timed.
  const auto ticks = [&](test::LoopbackBench& b) {
    if (b.device->status().state != DeviceState::idle) b.device->reset();
    b.device->frame(box, FrameOptions{3000, 1});
    const std::uint64_t before = b.board.state().executor.ticks;
    b.device->frame(box, FrameOptions{3000, 5});
    return b.board.state().executor.ticks - before;
  };
  EXPECT_EQ(ticks(bench), ticks(clean));
}

// What re-sending costs: the words of each list's preamble, counted on the wire.
TEST(LmcSettingsResent, ThePreambleHoldsEverySetting) {
  test::LoopbackBench bench({}, {}, test::quick_options(), kScale);
  run(bench, test::header_with(blanking_pen()), blanking_job());
  run(bench, test::header_with(blanking_pen()), blanking_job());
  const auto packets = bench.board.packets();
  ASSERT_EQ(packets.size(), 2u);
  for (const auto& p : packets) {
    std::vector<std::uint16_t> ops;
    for (std::size_t i = 0; i < 11; ++i) ops.push_back(p[i].opcode());
    const std::vector<Op> want{Op::ReadyMark,     Op::DelayTime,   Op::ListWritePort, Op::JumpSpeed,
                               Op::QSwitchPeriod, Op::MarkCurrent, Op::MarkSpeed,     Op::LaserOnDelay,
                               Op::LaserOffDelay, Op::PolygonDelay, Op::JumpDelay};
    for (std::size_t i = 0; i < want.size(); ++i) EXPECT_EQ(ops[i], std::uint16_t(want[i])) << i;
  }
}

}  // namespace
}  // namespace mark::lmc
