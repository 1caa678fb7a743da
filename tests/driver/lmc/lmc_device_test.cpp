// LmcDevice against the emulated board over the loopback link: the init sequence in order, the
// golden job through the whole device, READY flow control (never a packet while READY is
// clear, none lost), every injected fault (withheld READY, stall, hang, unplug) turning into a
// fault report with the laser port off where the board can be reached, abort from every state,
// refusals before anything is sent, pause / resume, framing, the capture file.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <thread>

#include "driver/lmc/capture_link.hpp"
#include "driver/lmc/job_encoder.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc {
namespace {

using test::LoopbackBench;

using test::fast_pen;
using test::figure;
using test::zigzag;

// What the board should have received for a job: the same encoder, fresh.
std::vector<std::vector<Word>> expected_packets(const DevicePen& pen,
                                                const std::vector<DeviceCommand>& commands) {
  const LmcOptions o = test::quick_options();
  const FieldUnits units(o.field_mm, o.axes, o.polygon_delay_unit);
  std::vector<std::vector<Word>> out;
  JobEncoder enc(units, [&](const ListPacket& p, const PacketInfo&) {
    std::vector<Word> words;
    for (std::size_t i = 0; i < kCommandsPerPacket; ++i) words.push_back(load(p.bytes().data() + 12 * i));
    out.push_back(words);
  });
  const BoardPen bp = encode_pen(pen, 0, units);
  enc.start_list(0.008, 1);
  enc.apply_pen(bp);
  for (std::size_t i = 0; i < commands.size(); ++i) enc.add(commands[i], i);
  enc.finish(commands.size());
  return out;
}

// The board's state once the stop sequence's flush list (a lone EndOfList, one tick) has run.
BoardState settled(const EmulatedBoard& board) {
  for (int i = 0; i < 500 && board.state().executing; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return board.state();
}

void expect_laser_off(const EmulatedBoard& board, const char* when) {
  const BoardState s = settled(board);
  EXPECT_EQ(s.port & 0x0001, 0) << when;
  EXPECT_FALSE(s.laser_emitting) << when;
  EXPECT_FALSE(s.executing) << when;
  EXPECT_FALSE(s.mo_open) << when;
}

TEST(LmcDevice, InitSequenceGoesOutInOrder) {
  LoopbackBench bench;
  const std::vector<Word> want = test::expected_init();
  const auto got = test::singles(bench.board.wire());
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i)
    EXPECT_EQ(got[i], want[i]) << i << ": " << describe(got[i], bench.board.units());
  EXPECT_EQ(bench.device->identity().serial, "4C4D4301");
  EXPECT_EQ(bench.device->identity().version, (std::array<std::uint16_t, 3>{1, 0x10, 2}));
  EXPECT_TRUE(bench.board.violations().empty());
  const DeviceDescription d = bench.device->describe();
  EXPECT_EQ(d.level, DeviceLevel::commands);
  EXPECT_FALSE(d.arcs);
  EXPECT_DOUBLE_EQ(d.chord_tolerance_mm, 0.005);
  EXPECT_DOUBLE_EQ(d.field_mm, 110);
  EXPECT_EQ(d.name, "lmc 4C4D4301");
}

TEST(LmcDevice, CorrectionTableIsUploadedLineByLine) {
  EmulatedBoard board;
  board.start_clock();
  LmcOptions o = test::quick_options();
  CorrectionTable t;
  t.scale = 65536.0 / 110;  // made for the 110 mm lens
  t.entries.resize(kCorEntries);
  for (std::size_t i = 0; i < kCorEntries; ++i)
    t.entries[i] = {encode_cor_delta(std::int64_t(i % 100) - 50), encode_cor_delta(7)};
  o.correction = t;
  LmcDevice device(std::make_unique<LoopbackLink>(board), o);
  const BoardState s = board.state();
  EXPECT_EQ(s.cor_table, 1);
  EXPECT_EQ(s.cor_lines, kCorEntries);
  EXPECT_TRUE(board.violations().empty());
  const auto singles = test::singles(board.wire());
  ASSERT_GT(singles.size(), 5 + kCorEntries);
  EXPECT_EQ(singles[4], word(Op::WriteCorTable, 1));
  EXPECT_EQ(singles[5], word(Op::WriteCorLine, encode_cor_delta(-50), 7, 0));
  EXPECT_EQ(singles[6], word(Op::WriteCorLine, encode_cor_delta(-49), 7, 1));
  EXPECT_EQ(singles[5 + kCorEntries], word(Op::EnableLaser));
}

TEST(LmcDevice, GoldenJobThroughTheDevice) {
  LoopbackBench bench(test::golden_board(), {}, test::golden_options(), /*time_scale=*/40);
  LmcDevice& dev = *bench.device;
  dev.begin_job(test::header_with(test::golden_pen()));
  const auto cmds = test::golden_rectangle_commands();
  dev.submit(cmds);
  const DeviceReport r = dev.end_job();
  ASSERT_EQ(r.outcome, DeviceState::done) << (r.fault ? r.fault->message : "");
  EXPECT_EQ(r.commands_done, 5u);
  EXPECT_EQ(figure(r, "commands"), 5);
  EXPECT_EQ(figure(r, "packets"), 1);
  EXPECT_EQ(figure(r, "list_commands"), 18);
  EXPECT_EQ(figure(r, "list_commands_per_packet"), 18);

  const auto packets = bench.board.packets();
  ASSERT_EQ(packets.size(), 1u);
  const auto golden = test::golden_rectangle_words();
  for (std::size_t i = 0; i < kCommandsPerPacket; ++i)
    EXPECT_EQ(packets[0][i], i < golden.size() ? golden[i] : word(Op::EndOfList)) << i;

  // The singles of the job, after the init: start, the packet's SetEndOfList, ExecuteList
  // (a short job: after its only packet), the status polls, the end.
  const auto all = test::singles(bench.board.wire());
  ASSERT_GE(all.size(), 20u + 9u);
  const std::vector<Word> singles(all.begin() + 20, all.end());
  EXPECT_EQ(singles[0], word(Op::ResetList));
  EXPECT_EQ(singles[1], word(Op::WritePort, 1));
  EXPECT_EQ(singles[2], word(Op::FiberSetMo, 1));
  EXPECT_EQ(singles[3], word(Op::GetVersion));  // READY?
  EXPECT_EQ(singles[4], word(Op::SetEndOfList, 0));
  EXPECT_EQ(singles[5], word(Op::ExecuteList));
  const std::size_t n = singles.size();
  EXPECT_EQ(singles[n - 3], word(Op::FiberSetMo, 0));
  EXPECT_EQ(singles[n - 2], word(Op::WritePort, 0));
  EXPECT_EQ(singles[n - 1], word(Op::GetMarkTime, 3));
  for (std::size_t i = 6; i < n - 3; ++i) EXPECT_EQ(singles[i], word(Op::GetVersion)) << i;

  // The board ran the rectangle: 40 mm at 8 units/ms (13.43 mm/s) lit, after the jump.
  const BoardState s = bench.board.state();
  EXPECT_TRUE(s.finished);
  EXPECT_EQ(s.executor.moves, 5u);
  EXPECT_EQ(s.executor.distance_mismatches, 0u);
  const double lit_s = double(s.executor.lit_ticks) * 10e-6;
  EXPECT_NEAR(lit_s, 4 * 5958.0 / 8e3, 0.001);  // on delay = off delay: lit as long as marked
  EXPECT_TRUE(bench.board.violations().empty());
  expect_laser_off(bench.board, "after the job");
}

TEST(LmcDevice, FlowControlNeverSendsWhileNotReadyAndLosesNothing) {
  BoardOptions bo;
  bo.list_capacity = 4;
  LoopbackBench bench(bo);
  const auto cmds = zigzag(3000);
  const DevicePen pen = fast_pen();
  bench.device->begin_job(test::header_with(pen));
  // In pieces, as a job runner would hand them over.
  for (std::size_t i = 0; i < cmds.size(); i += 100)
    bench.device->submit(std::span(cmds).subspan(i, std::min<std::size_t>(100, cmds.size() - i)));
  const DeviceReport r = bench.device->end_job();
  ASSERT_EQ(r.outcome, DeviceState::done) << (r.fault ? r.fault->message : "");

  const auto want = expected_packets(pen, cmds);
  const auto got = bench.board.packets();
  ASSERT_EQ(got.size(), want.size());
  EXPECT_EQ(got, want);
  EXPECT_EQ(figure(r, "packets"), double(want.size()));
  EXPECT_GT(figure(r, "ready_waits"), 0) << "the job never filled the board's buffer";
  std::size_t packets = 0;
  for (const WireRecord& w : bench.board.wire())
    if (w.packet) {
      ++packets;
      EXPECT_TRUE(w.status & status::ready) << "packet " << w.packet_number << " sent while READY was clear";
    }
  EXPECT_EQ(packets, want.size());
  const BoardState s = bench.board.state();
  EXPECT_EQ(s.packets_lost, 0u);
  EXPECT_EQ(s.executor.underrun_events, 0u);
  EXPECT_EQ(s.executor.moves, cmds.size());
  EXPECT_TRUE(bench.board.violations().empty());
  // ExecuteList went out once, right after the third packet.
  std::size_t seen_packets = 0, executes = 0;
  for (const WireRecord& w : bench.board.wire()) {
    if (w.packet) ++seen_packets;
    else if (w.single == word(Op::ExecuteList)) {
      ++executes;
      EXPECT_EQ(seen_packets, 3u);
    }
  }
  EXPECT_EQ(executes, 1u);
}

TEST(LmcDevice, WithheldReadyDelaysThePacketsButLosesNone) {
  BoardFaults f;
  f.withhold_ready_after_packet = 1;
  f.withhold_ready_s = 0.15;
  LoopbackBench bench({}, f);
  const auto cmds = zigzag(1000);
  bench.device->begin_job(test::header_with(fast_pen()));
  bench.device->submit(cmds);
  const DeviceReport r = bench.device->end_job();
  ASSERT_EQ(r.outcome, DeviceState::done) << (r.fault ? r.fault->message : "");
  EXPECT_EQ(bench.board.packets(), expected_packets(fast_pen(), cmds));
  EXPECT_GE(figure(r, "ready_waits"), 1);
  EXPECT_GE(figure(r, "ready_wait_s"), 0.1);
  for (const WireRecord& w : bench.board.wire())
    if (w.packet) {
      EXPECT_TRUE(w.status & status::ready) << w.packet_number;
    }
  EXPECT_TRUE(bench.board.violations().empty());
}

// READY withheld for good after the fourth packet: the list runs out of what it has, stays
// BUSY waiting for more, and the host gives up once the list has run twice its estimate and
// the grace (0.1 s here) without making room.
TEST(LmcDevice, ReadyThatNeverReturnsIsATimeoutFault) {
  BoardFaults f;
  f.withhold_ready_after_packet = 4;
  f.withhold_ready_s = 30;
  LmcOptions o = test::quick_options();
  o.session.grace_s = 0.1;
  LoopbackBench bench({}, f, o);
  const auto cmds = zigzag(3000);
  bench.device->begin_job(test::header_with(fast_pen()));
  try {
    bench.device->submit(cmds);
    FAIL() << "no fault";
  } catch (const DeviceFaultError& e) {
    EXPECT_EQ(e.fault().category, FaultCategory::timeout);
    EXPECT_EQ(e.fault().at, 4 * 256u - 11u);  // four packets went out: 11 preamble words, then commands
    const std::string m = e.what();
    EXPECT_NE(m.find("the board did not become READY for the next list packet: it has run its list for"),
              std::string::npos) << m;
    EXPECT_NE(m.find("commands 0..1012 were sent and may have been marked; nothing from command 1013 on"),
              std::string::npos) << m;
    EXPECT_NE(m.find("; stopped, laser port off confirmed; acknowledged: WritePort(0x0000), StopExecute, "
                     "Fiber_SetMo(0), ResetList"),
              std::string::npos) << m;
  }
  EXPECT_EQ(bench.device->status().state, DeviceState::failed);
  EXPECT_EQ(bench.board.state().packets_received, 4u);
  expect_laser_off(bench.board, "after the READY timeout");
  const DeviceReport r = bench.device->end_job();
  EXPECT_EQ(r.outcome, DeviceState::failed);
  ASSERT_TRUE(r.fault);
}

TEST(LmcDevice, StallMidJobStopsTheJobAndTheLaserGoesOff) {
  BoardFaults f;
  f.stall_at_packet = 6;
  LoopbackBench bench({}, f);
  const auto cmds = zigzag(3000);
  bench.device->begin_job(test::header_with(fast_pen()));
  DeviceFault fault;
  try {
    bench.device->submit(cmds);
    FAIL() << "no fault";
  } catch (const DeviceFaultError& e) {
    fault = e.fault();
  }
  EXPECT_EQ(fault.category, FaultCategory::transport);
  // Five packets reached the board: 11 preamble words, then commands 0..1268 (a jump and marks).
  EXPECT_EQ(fault.at, 5 * 256u - 11u);
  EXPECT_NE(fault.message.find("endpoint stalled"), std::string::npos) << fault.message;
  EXPECT_NE(fault.message.find("commands 0..1268 were sent and may have been marked; nothing "
                               "from command 1269 on was marked"),
            std::string::npos)
      << fault.message;
  EXPECT_NE(fault.message.find("; stopped, laser port off confirmed"), std::string::npos) << fault.message;
  expect_laser_off(bench.board, "after the stall");
  const BoardState s = bench.board.state();
  EXPECT_LE(s.executor.moves, fault.at);  // it executed no more than was sent
  // Packets 1..5, then only the stop sequence's flush (a lone EndOfList): the stalled packet
  // was not retried.
  const auto packets = bench.board.packets();
  ASSERT_EQ(packets.size(), 6u);
  EXPECT_EQ(packets[5][0], word(Op::EndOfList));
  EXPECT_EQ(packets[5][0], packets[5][255]);
  const DeviceReport r = bench.device->end_job();
  EXPECT_EQ(r.outcome, DeviceState::failed);
  EXPECT_EQ(r.commands_done, fault.at);
}

TEST(LmcDevice, BoardThatStopsAnsweringIsATimeoutAndUnreachable) {
  BoardFaults f;
  f.hang_at_packet = 2;  // for good
  LoopbackBench bench({}, f);
  bench.device->begin_job(test::header_with(fast_pen()));
  try {
    bench.device->submit(zigzag(1000));
    FAIL() << "no fault";
  } catch (const DeviceFaultError& e) {
    EXPECT_EQ(e.fault().category, FaultCategory::timeout);
    const std::string m = e.what();
    EXPECT_NE(m.find("timed out"), std::string::npos) << m;
    EXPECT_NE(m.find("NOT confirmed stopped"), std::string::npos) << m;
    EXPECT_NE(m.find("laser port off NOT confirmed"), std::string::npos) << m;
    EXPECT_NE(m.find("the board could not be reached"), std::string::npos) << m;
  }
  const DeviceReport r = bench.device->end_job();
  EXPECT_EQ(r.outcome, DeviceState::failed);
  // One link timeout for the packet: the fault is known then (the stop sequence comes after).
  EXPECT_LT(figure(r, "fault_latency_s"), 0.1 + 0.1);
}

TEST(LmcDevice, UnplugMidJobIsReportedWithin200ms) {
  BoardFaults f;
  f.unplug_after_execute_s = 0.03;
  LoopbackBench bench({}, f);
  const auto cmds = zigzag(3000);  // about 0.3 s on the board
  bench.device->begin_job(test::header_with(fast_pen()));
  std::optional<DeviceFault> fault;
  try {
    bench.device->submit(cmds);
  } catch (const DeviceFaultError& e) {
    fault = e.fault();
  }
  const DeviceReport r = bench.device->end_job();
  EXPECT_EQ(r.outcome, DeviceState::failed);
  ASSERT_TRUE(r.fault);
  EXPECT_EQ(r.fault->category, FaultCategory::transport);
  EXPECT_NE(r.fault->message.find("no device"), std::string::npos) << r.fault->message;
  EXPECT_NE(r.fault->message.find("could not be reached"), std::string::npos) << r.fault->message;
  EXPECT_GT(r.fault->at, 0u);
  // The driver's own figure: from the last transfer that worked to the fault report.
  EXPECT_LT(figure(r, "fault_latency_s"), 0.2);
  std::printf("unplug reported %.1f ms after the last good transfer\n", 1e3 * figure(r, "fault_latency_s"));
  EXPECT_TRUE(bench.board.state().unplugged);
  EXPECT_THROW(bench.device->reset(), DeviceFaultError);  // still gone
}

TEST(LmcDevice, AbortFromEveryStateLeavesTheLaserPortOff) {
  LoopbackBench bench;
  LmcDevice& dev = *bench.device;
  const JobHeader h = test::header_with(fast_pen());

  // Idle, with the red pointer on.
  dev.set_red_pointer(true);
  EXPECT_EQ(bench.board.state().port, 0x0100);
  dev.abort();
  EXPECT_EQ(bench.board.state().port, 0);
  expect_laser_off(bench.board, "idle");
  EXPECT_EQ(dev.status().state, DeviceState::aborted);
  dev.reset();
  dev.abort();  // aborted twice
  dev.abort();
  expect_laser_off(bench.board, "aborted twice");
  dev.reset();

  // Running, nothing sent yet (the laser port is already enabled by begin_job).
  dev.begin_job(h);
  EXPECT_EQ(bench.board.state().port & 1, 1);
  EXPECT_TRUE(bench.board.state().mo_open);
  const std::size_t packets_before = bench.board.state().packets_received;
  dev.abort();
  expect_laser_off(bench.board, "begun");
  dev.submit(zigzag(10));  // after abort: nothing more goes out
  EXPECT_EQ(dev.end_job().outcome, DeviceState::aborted);
  EXPECT_EQ(bench.board.state().packets_received, packets_before + 1);  // the stop's flush
  dev.reset();

  // Running and marking: abort from another thread while submit waits for READY.
  dev.begin_job(h);
  std::thread producer([&] { dev.submit(zigzag(4000)); });
  for (int i = 0; i < 2000 && !bench.board.state().laser_emitting; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_TRUE(bench.board.state().laser_emitting);
  dev.abort();
  producer.join();
  expect_laser_off(bench.board, "marking");
  const std::size_t packets_at_abort = bench.board.state().packets_received;
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_EQ(bench.board.state().packets_received, packets_at_abort);  // nothing after the stop
  EXPECT_FALSE(bench.board.state().laser_emitting);
  const DeviceReport aborted = dev.end_job();
  EXPECT_EQ(aborted.outcome, DeviceState::aborted);
  dev.reset();

  // Paused.
  dev.begin_job(h);
  std::thread producer2([&] { dev.submit(zigzag(3000)); });
  for (int i = 0; i < 2000 && !bench.board.state().executing; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  dev.pause();
  EXPECT_TRUE(bench.board.state().paused);
  dev.abort();
  producer2.join();
  expect_laser_off(bench.board, "paused");
  dev.end_job();
  dev.reset();

  // Done.
  dev.begin_job(h);
  dev.submit(zigzag(20));
  EXPECT_EQ(dev.end_job().outcome, DeviceState::done);
  dev.abort();
  expect_laser_off(bench.board, "done");
  dev.reset();
  EXPECT_TRUE(bench.board.violations().empty());
}

TEST(LmcDevice, AbortAfterAFaultStillSwitchesOff) {
  BoardFaults f;
  f.stall_at_packet = 4;
  LoopbackBench bench({}, f);
  bench.device->begin_job(test::header_with(fast_pen()));
  EXPECT_THROW(bench.device->submit(zigzag(2000)), DeviceFaultError);
  bench.device->abort();
  expect_laser_off(bench.board, "failed, then aborted");
  EXPECT_EQ(bench.device->status().state, DeviceState::failed);  // the fault is kept
}

TEST(LmcDevice, PauseHoldsAndResumeFinishesTheJob) {
  LoopbackBench bench;
  LmcDevice& dev = *bench.device;
  const auto cmds = zigzag(1500);
  dev.begin_job(test::header_with(fast_pen()));
  dev.submit(cmds);  // 6 packets: the last ones wait for room, so the list is running
  dev.pause();
  EXPECT_EQ(dev.query_status() & (status::busy | status::paused), status::busy | status::paused);
  const std::uint64_t moves = bench.board.state().executor.moves;
  std::this_thread::sleep_for(std::chrono::milliseconds(60));
  BoardState s = bench.board.state();
  EXPECT_TRUE(s.paused);
  EXPECT_FALSE(s.laser_emitting);
  EXPECT_LE(s.executor.moves, moves + 1);  // held (the move in progress may have been counted)
  dev.resume();
  const DeviceReport r = dev.end_job();
  ASSERT_EQ(r.outcome, DeviceState::done) << (r.fault ? r.fault->message : "");
  s = bench.board.state();
  EXPECT_EQ(s.executor.moves, cmds.size());
  EXPECT_EQ(s.executor.underrun_events, 0u);
  EXPECT_TRUE(bench.board.violations().empty());
  EXPECT_EQ(dev.query_status() & status::busy, 0);
  // Where the mirrors stopped: the serpentine's last point.
  const Vec2 at = dev.query_position();
  EXPECT_NEAR(at.x, cmds.back().x_mm, 0.002);
  EXPECT_NEAR(at.y, cmds.back().y_mm, 0.002);
}

TEST(LmcDevice, OutOfFieldIsRefusedBeforeAnythingOfItIsSent) {
  LoopbackBench bench;
  LmcDevice& dev = *bench.device;
  dev.begin_job(test::header_with(fast_pen()));
  std::vector<DeviceCommand> cmds = zigzag(300);
  cmds[200] = DeviceCommand::mark_to(55.2, 1.5);
  try {
    dev.submit(cmds);
    FAIL() << "no refusal";
  } catch (const DeviceFaultError& e) {
    EXPECT_EQ(e.fault().category, FaultCategory::out_of_field);
    EXPECT_EQ(e.fault().at, 0u);
    const std::string m = e.what();
    EXPECT_NE(m.find("command 200 (mark)"), std::string::npos) << m;
    EXPECT_NE(m.find("(55.2000, 1.5000) mm lies outside the 110 mm field"), std::string::npos) << m;
    EXPECT_NE(m.find("nothing was marked"), std::string::npos) << m;
  }
  // The 300 commands' packet was never sent; only the stop's flush packet was.
  EXPECT_EQ(bench.board.state().packets_received, 1u);
  EXPECT_EQ(bench.board.packets()[0][0], word(Op::EndOfList));
  expect_laser_off(bench.board, "refused");

  // A job field larger than the lens, an arc, a bad pen: refused with the reason.
  dev.reset();
  EXPECT_THROW(dev.begin_job(test::header_with(fast_pen(), 120)), DeviceError);
  DevicePen slow = fast_pen();
  slow.mark_speed_mm_s = 0.5;
  try {
    dev.begin_job(test::header_with(slow));
    FAIL();
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("pen 0: mark speed 0.5 mm/s"), std::string::npos) << e.what();
  }
  EXPECT_EQ(dev.status().state, DeviceState::idle);
  dev.begin_job(test::header_with(fast_pen()));
  const std::vector<DeviceCommand> arc{DeviceCommand::arc_to(1, 0, 0.5, 0, 3.14)};
  try {
    dev.submit(arc);
    FAIL();
  } catch (const DeviceFaultError& e) {
    EXPECT_NE(std::string(e.what()).find("takes no arcs"), std::string::npos) << e.what();
  }
}

TEST(LmcDevice, JobsFollowEachOtherAndResetRecoversFromAFault) {
  BoardFaults f;
  f.stall_at_packet = 3;  // jobs 1 and 2 send one packet each; job 3's first one stalls
  LoopbackBench bench({}, f);
  LmcDevice& dev = *bench.device;
  dev.begin_job(test::header_with(fast_pen()));
  dev.submit(zigzag(51));  // ends away from the centre
  EXPECT_EQ(dev.end_job().outcome, DeviceState::done);
  EXPECT_THROW(dev.begin_job(test::header_with(fast_pen())), DeviceError);  // done: reset first
  dev.reset();

  // Job 2 starts with a mark: the mirrors are where job 1 left them, so the device goes back
  // to the field centre first (the DeviceCommand contract).
  dev.begin_job(test::header_with(fast_pen()));
  const std::vector<DeviceCommand> mark_first{DeviceCommand::mark_to(1, 1)};
  dev.submit(mark_first);
  EXPECT_EQ(dev.end_job().outcome, DeviceState::done);
  const auto p2 = bench.board.packets().at(1);
  std::size_t first_move = 0;
  while (p2[first_move].opcode() != static_cast<std::uint16_t>(Op::JumpTo) &&
         p2[first_move].opcode() != static_cast<std::uint16_t>(Op::MarkTo))
    ++first_move;
  EXPECT_EQ(p2[first_move].opcode(), static_cast<std::uint16_t>(Op::JumpTo));
  EXPECT_EQ(p2[first_move].p(1), 0x8000);
  EXPECT_EQ(p2[first_move].p(2), 0x8000);
  dev.reset();

  dev.begin_job(test::header_with(fast_pen()));
  dev.submit(zigzag(50));
  const DeviceReport failed = dev.end_job();
  ASSERT_EQ(failed.outcome, DeviceState::failed);
  EXPECT_EQ(failed.fault->category, FaultCategory::transport);
  dev.reset();  // reopens, initialises again, asks where the mirrors are
  EXPECT_EQ(dev.status().state, DeviceState::idle);
  dev.begin_job(test::header_with(fast_pen()));
  dev.submit(zigzag(50));
  EXPECT_EQ(dev.end_job().outcome, DeviceState::done);
  EXPECT_EQ(bench.board.state().executor.distance_mismatches, 0u);
  for (const std::string& v : bench.board.violations()) ADD_FAILURE() << v;
}

TEST(LmcDevice, FrameTracesWithTheRedPointerAndNeverTheLaser) {
  LoopbackBench bench({}, {}, test::quick_options(), 4);
  const std::vector<std::vector<Vec2>> box{{{-5, -2}, {5, -2}, {5, 2}, {-5, 2}, {-5, -2}}};
  FrameOptions o;
  o.laps = 3;
  const FrameReport r = bench.device->frame(box, o);
  EXPECT_EQ(r.laps, 3u);
  EXPECT_FALSE(r.stopped);
  const BoardState s = bench.board.state();
  EXPECT_EQ(s.executor.lit_ticks, 0u);
  EXPECT_EQ(s.port, 0);  // red pointer off again at the end
  EXPECT_FALSE(s.mo_open);
  // The start, the five corners of the first lap, then four per lap (a lap ends where the
  // next begins: the move there is dropped).
  const auto path = bench.board.red_path();
  ASSERT_EQ(path.size(), 1 + 5 + 2 * 4u);
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Vec2 want = box[0][i <= 5 ? i - 1 : 1 + (i - 6) % 4];
    EXPECT_NEAR(path[i].x, want.x, 0.002) << i;
    EXPECT_NEAR(path[i].y, want.y, 0.002) << i;
  }
  for (const auto& p : bench.board.packets())
    for (const Word& w : p) EXPECT_NE(w.opcode(), static_cast<std::uint16_t>(Op::MarkTo));
  EXPECT_TRUE(bench.board.violations().empty());
  EXPECT_EQ(bench.device->status().state, DeviceState::idle);
}

TEST(LmcDevice, FrameRunsUntilAbortThenTheRedPointerGoesOff) {
  LoopbackBench bench;
  const std::vector<std::vector<Vec2>> box{{{-5, -2}, {5, -2}, {5, 2}, {-5, 2}, {-5, -2}}};
  FrameReport r;
  std::thread t([&] { r = bench.device->frame(box, FrameOptions{}); });
  for (int i = 0; i < 2000 && bench.board.red_path().size() < 40; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(bench.board.state().port, 0x0100);
  bench.device->abort();
  t.join();
  EXPECT_TRUE(r.stopped);
  EXPECT_GT(r.laps, 10u);
  const BoardState s = settled(bench.board);
  EXPECT_EQ(s.port, 0);
  EXPECT_FALSE(s.executing);
  EXPECT_EQ(s.executor.lit_ticks, 0u);
}

TEST(LmcDevice, CaptureHoldsExactlyTheBytesForEndpoint2) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("lmc_capture_" + std::to_string(::getpid()) + ".lmc")).string();
  {
    LmcDevice dev(std::make_unique<CaptureLink>(path), test::golden_options());
    dev.begin_job(test::header_with(test::golden_pen()));
    dev.submit(test::golden_rectangle_commands());
    const DeviceReport r = dev.end_job();
    ASSERT_EQ(r.outcome, DeviceState::done);
  }
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const auto records = read_capture(path);
  std::vector<Word> singles;
  std::vector<std::vector<Word>> packets;
  for (const CaptureRecord& r : records) {
    if (r.packet) packets.push_back(r.words);
    else singles.push_back(r.words.at(0));
  }
  ASSERT_EQ(packets.size(), 1u);
  const auto golden = test::golden_rectangle_words();
  for (std::size_t i = 0; i < kCommandsPerPacket; ++i)
    EXPECT_EQ(packets[0][i], i < golden.size() ? golden[i] : word(Op::EndOfList)) << i;
  // 20 init commands, ResetList, WritePort(1), Fiber_SetMo(1), GetVersion (READY), the packet,
  // SetEndOfList, ExecuteList, GetVersion (not BUSY), Fiber_SetMo(0), WritePort(0), GetMarkTime.
  ASSERT_EQ(singles.size(), 20u + 10u);
  EXPECT_EQ(singles[0], word(Op::GetSerialNo));
  EXPECT_EQ(singles[20], word(Op::ResetList));
  EXPECT_EQ(singles[24], word(Op::SetEndOfList, 0));
  EXPECT_EQ(singles[25], word(Op::ExecuteList));
  EXPECT_EQ(singles[29], word(Op::GetMarkTime, 3));
  EXPECT_EQ(std::filesystem::file_size(path), 30 * 13u + 3073u);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mark::lmc
