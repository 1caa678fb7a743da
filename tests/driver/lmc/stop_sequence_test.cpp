// The stop sequence with each of its commands answered wrongly in turn — a stall, no answer, a
// write that hangs past the link's timeout, an unplug — while a job runs on the emulated board:
// every later command is still written where the link allows, "stopped" is claimed only when
// StopExecute and Fiber_SetMo(0) were acknowledged, and the outcome names each command that was
// not.
#include <gtest/gtest.h>

#include <thread>

#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc {
namespace {

struct Case {
  const char* name;       // the command, for the test name
  Op op;
  std::size_t occurrence;  // counted from when the fault is armed, just before the stop
  std::size_t step;        // its index in StopOutcome::steps
  SingleFault::Kind kind;
};

const char* kind_name(SingleFault::Kind k) {
  switch (k) {
    case SingleFault::Kind::stall: return "Stall";
    case SingleFault::Kind::no_answer: return "NoAnswer";
    case SingleFault::Kind::hang: return "Hang";
    case SingleFault::Kind::unplug: return "Unplug";
  }
  return "?";
}

// The stop sequence as StopOutcome lists it: WritePort, StopExecute, Fiber_SetMo(0), ResetList,
// GetVersion (READY for the flush?), the flush list, WritePort.
constexpr std::size_t kSteps = 7;

std::vector<Case> cases() {
  const struct {
    const char* name;
    Op op;
    std::size_t occurrence, step;
  } commands[] = {{"FirstWritePort", Op::WritePort, 1, 0}, {"StopExecute", Op::StopExecute, 1, 1},
                  {"FiberSetMo", Op::FiberSetMo, 1, 2},    {"ResetList", Op::ResetList, 1, 3},
                  {"StatusPoll", Op::GetVersion, 1, 4},    {"LastWritePort", Op::WritePort, 2, 6}};
  std::vector<Case> out;
  for (const auto& c : commands)
    for (auto k : {SingleFault::Kind::stall, SingleFault::Kind::no_answer, SingleFault::Kind::hang,
                   SingleFault::Kind::unplug})
      out.push_back({c.name, c.op, c.occurrence, c.step, k});
  return out;
}

// Failure messages name the case, not its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name << kind_name(c.kind); }

class LmcStopSequence : public ::testing::TestWithParam<Case> {};

TEST_P(LmcStopSequence, EveryCommandIsWrittenWhereTheLinkAllows) {
  const Case c = GetParam();
  test::LoopbackBench bench;
  LmcDevice& dev = *bench.device;
  dev.begin_job(test::header_with(test::fast_pen()));
  dev.submit(test::zigzag(1000));  // four packets, all sent: the list runs for about 0.1 s
  ASSERT_TRUE(bench.board.state().executing);
  const std::size_t wire_before = bench.board.wire().size();
  bench.board.set_single_fault({static_cast<std::uint16_t>(c.op), c.occurrence, c.kind});
  dev.abort();
  const StopOutcome o = dev.last_stop();
  ASSERT_EQ(o.steps.size(), kSteps);

  using R = StopStep::Result;
  const StopStep& failed = o.steps[c.step];
  const bool unplugged = c.kind == SingleFault::Kind::unplug;
  switch (c.kind) {
    case SingleFault::Kind::stall: EXPECT_EQ(failed.result, R::acknowledged) << "cleared and written again"; break;
    case SingleFault::Kind::no_answer: EXPECT_EQ(failed.result, R::unanswered); break;
    case SingleFault::Kind::hang:
    case SingleFault::Kind::unplug: EXPECT_EQ(failed.result, R::not_written); break;
  }
  // Every later command: written and acknowledged, unless the board is gone (the flush list is
  // skipped when its status poll failed).
  for (std::size_t i = c.step + 1; i < kSteps; ++i) {
    const StopStep& s = o.steps[i];
    if (unplugged) {
      EXPECT_EQ(s.result, R::unreachable) << s.command;
    } else if (i == 5 && c.step == 4 && c.kind != SingleFault::Kind::stall) {
      EXPECT_EQ(s.result, R::skipped) << s.command;
    } else {
      EXPECT_EQ(s.result, R::acknowledged) << s.command << ": " << s.why;
    }
  }
  // The board got every later command the link let through.
  std::vector<Word> after;
  const auto wire = bench.board.wire();
  for (std::size_t i = wire_before; i < wire.size(); ++i)
    if (!wire[i].packet) after.push_back(wire[i].single);
  const auto received = [&](Op op) {
    return std::count_if(after.begin(), after.end(), [&](const Word& w) { return w.opcode() == std::uint16_t(op); });
  };
  if (!unplugged) {
    // The failing command reached the board unless its write hung; every other one did.
    const auto want = [&](Op op, int times) {
      return c.op == op && c.kind == SingleFault::Kind::hang ? times - 1 : times;
    };
    EXPECT_GE(received(Op::StopExecute), want(Op::StopExecute, 1));
    EXPECT_GE(received(Op::FiberSetMo), want(Op::FiberSetMo, 1));
    EXPECT_GE(received(Op::ResetList), want(Op::ResetList, 1));
    EXPECT_GE(received(Op::WritePort), want(Op::WritePort, 2));
    // Stopped (StopExecute, or the ResetList after it) and the port off; the flush list's
    // single EndOfList may still be running for a tick.
    for (int i = 0; i < 200 && bench.board.state().executing; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    EXPECT_FALSE(bench.board.state().executing);
    EXPECT_EQ(bench.board.state().port & 1, 0);
  }
  // "stopped" only with StopExecute and Fiber_SetMo(0) acknowledged.
  const bool stop_acked = o.steps[1].result == R::acknowledged && o.steps[2].result == R::acknowledged;
  EXPECT_EQ(o.stopped, stop_acked);
  const std::string summary = o.summary();
  EXPECT_EQ(summary.starts_with("stopped"), stop_acked) << summary;
  if (failed.result != R::acknowledged) {
    EXPECT_NE(summary.find(failed.command + " " + std::string(to_string(failed.result))), std::string::npos) << summary;
  }
  const DeviceReport r = dev.end_job();
  EXPECT_EQ(r.outcome, DeviceState::aborted);
  EXPECT_EQ(test::figure(r, "stop_confirmed"), stop_acked ? 1 : 0);
}

INSTANTIATE_TEST_SUITE_P(EachCommandFailing, LmcStopSequence, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           return std::string(i.param.name) + kind_name(i.param.kind);
                         });

// A fault mid-job: the fault's message carries the same account.
TEST(LmcStopSequenceFault, TheFaultSaysWhichStopCommandsWereNotAcknowledged) {
  BoardFaults f;
  f.stall_at_packet = 3;
  test::LoopbackBench bench({}, f);
  bench.board.set_single_fault({static_cast<std::uint16_t>(Op::StopExecute), 1, SingleFault::Kind::no_answer});
  bench.device->begin_job(test::header_with(test::fast_pen()));
  try {
    bench.device->submit(test::zigzag(2000));
    FAIL() << "no fault";
  } catch (const DeviceFaultError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("NOT confirmed stopped (StopExecute and Fiber_SetMo(0) must both be acknowledged), "
                     "laser port off confirmed"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("StopExecute written, no answer"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace mark::lmc
