// Long jobs in real time (the board's clock at 1 × the wall clock), under every behaviour
// variant of the emulated board: a job of more than 3 s of board time runs to done, and a red-
// pointer frame of 5 s. Before the session's deadline followed the board (it counted the time
// since ExecuteList twice), the golden rectangle at 15 mm/s failed after 2.0 s of its 3.0 s.
// Each run prints the estimate, the board's own time and what the host waited: the figures of
// docs/lmc.md, "Long jobs". These tests cost wall time, not CPU: about 3.2 s each.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc {
namespace {

using Clock = std::chrono::steady_clock;

// The golden rectangle at 15 mm/s (about 2.7 s of marking), then 2000 short marks at 2000 mm/s
// with a corner at each (whole ticks, polygon delays, laser delays and their waits all count).
std::vector<DeviceCommand> long_job() {
  std::vector<DeviceCommand> c = test::golden_rectangle_commands();
  c.push_back(DeviceCommand::jump_to(-10, 0));
  for (int i = 1; i <= 2000; ++i) {
    const double x = -10 + 0.011 * i, y = (i % 2) ? 0.07 : 0.0;
    c.push_back(DeviceCommand::mark_to(x, y, 2000));
    if (i % 50 == 0) c.push_back(DeviceCommand::jump_to(x + 0.2, 0.5));  // travel, mark delay
  }
  return c;
}

class LmcRealTime : public ::testing::TestWithParam<BoardVariant> {};

TEST_P(LmcRealTime, AJobOfMoreThanThreeSecondsRunsToDone) {
  const BoardVariant v = GetParam();
  test::LoopbackBench bench(with_variant({}, v.name), {}, test::quick_options(), /*time_scale=*/1);
  LmcDevice& dev = *bench.device;
  const auto t0 = Clock::now();
  dev.begin_job(test::header_with(test::golden_pen()));
  dev.submit(long_job());
  const DeviceReport r = dev.end_job();
  const double wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
  ASSERT_EQ(r.outcome, DeviceState::done) << v.name << ": " << (r.fault ? r.fault->message : "");
  const BoardState s = bench.board.state();
  const double board_s = double(s.executor.ticks) * 10e-6;
  const double estimate_s = test::figure(r, "estimated_time_s");
  const double waited_s = test::figure(r, "ready_wait_s") + test::figure(r, "idle_wait_s");
  std::printf("%-16s estimate %6.3f s  board %6.3f s (%5.3f ×)  device_time %6.3f s  host waited %6.3f s  wall %6.3f s\n",
              std::string(v.name).c_str(), estimate_s, board_s, board_s / estimate_s, r.device_time_s, waited_s,
              wall_s);
  EXPECT_GE(board_s, 3.0);
  EXPECT_EQ(s.executor.underrun_events, 0u) << v.name;
  EXPECT_EQ(s.executor.distance_mismatches, 0u);
  EXPECT_EQ(s.packets_lost, 0u);
  for (const std::string& e : bench.board.violations()) ADD_FAILURE() << v.name << ": " << e;
  // The host saw the board finish: its measured time is the board's, to the poll interval and
  // the wall clock's scheduling.
  EXPECT_NEAR(r.device_time_s, board_s, 0.1);
  EXPECT_GE(estimate_s, 2.9);
}

// A 5 s frame: 300 laps of a 20 × 5 mm box at the red-light speed, 3000 mm/s (16.7 ms a lap;
// `marker frame` with 300 laps failed after 4.1 s before).
TEST_P(LmcRealTime, AFiveSecondFrameRunsAllItsLaps) {
  const BoardVariant v = GetParam();
  if (v.name != "reference" && v.name != "slowest") GTEST_SKIP() << "the frame runs on two variants";
  test::LoopbackBench bench(with_variant({}, v.name), {}, test::quick_options(), /*time_scale=*/1);
  const std::vector<std::vector<Vec2>> box{{{-10, -2.5}, {10, -2.5}, {10, 2.5}, {-10, 2.5}, {-10, -2.5}}};
  const std::uint64_t ticks_before = bench.board.state().executor.ticks;
  const FrameReport r = bench.device->frame(box, FrameOptions{3000, 300});
  const BoardState s = bench.board.state();
  const double board_s = double(s.executor.ticks - ticks_before) * 10e-6;
  std::printf("%-16s frame: %llu laps, %llu packets, board %.3f s\n", std::string(v.name).c_str(),
              static_cast<unsigned long long>(r.laps), static_cast<unsigned long long>(r.packets), board_s);
  EXPECT_EQ(r.laps, 300u);
  EXPECT_FALSE(r.stopped);
  EXPECT_GE(board_s, 5.0);
  EXPECT_EQ(s.executor.lit_ticks, 0u);
  EXPECT_EQ(s.port, 0);
  EXPECT_EQ(s.executor.underrun_events, 0u);
  EXPECT_EQ(bench.device->status().state, DeviceState::idle);
}

INSTANTIATE_TEST_SUITE_P(EveryBoardVariant, LmcRealTime, ::testing::ValuesIn(board_variants().begin(), board_variants().end()),
                         [](const ::testing::TestParamInfo<BoardVariant>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace mark::lmc
