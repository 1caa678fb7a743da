// The emulated board on its own: list execution on the 10 µs clock (move timing, laser on / off
// delays, polygon and jump delays, LaserOnPoint, the output-port and oscillator gates, underrun),
// READY / BUSY, and the host checks it records. The clock is stepped by hand, so every figure
// is exact.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "tests/driver/lmc/board_rig.hpp"

namespace mark::lmc {
namespace {

using test::at;
using test::move;
using test::Rig;

TEST(LmcBoard, MovesTakeWholeTicksAtTheSetSpeedAndLandOnTheTarget) {
  Rig rig;
  rig.arm();
  const auto c = at(0, 0);
  const std::array<std::uint16_t, 2> a{c[0], c[1]}, b{std::uint16_t(c[0] + 1000), c[1]};
  // Jump 1000 units at 200 units/ms (2 units/tick): 500 ticks. Mark back at 300 units/ms
  // (3 units/tick): ⌈1000/3⌉ = 334 ticks.
  rig.packet({word(Op::JumpSpeed, 200), word(Op::MarkSpeed, 300), move(Op::JumpTo, a, b),
              move(Op::MarkTo, b, a), word(Op::EndOfList)});
  rig.single(word(Op::ExecuteList));
  EXPECT_TRUE(rig.board.state().status & status::busy);
  rig.board.advance(0.01);  // 1000 ticks: more than enough
  const auto& s = rig.sink.samples;
  ASSERT_EQ(s.size(), 500u + 334u);
  const double mm = 1 / FieldUnits(110).units_per_mm();
  EXPECT_NEAR(s[249].x_mm, 500 * mm, 1e-4);   // halfway through the jump
  EXPECT_NEAR(s[499].x_mm, 1000 * mm, 1e-4);  // on the target
  EXPECT_NEAR(s.back().x_mm, 0, 1e-4);
  EXPECT_EQ(rig.count_lit(), 334u);  // the mark, no delays set
  const BoardState st = rig.board.state();
  EXPECT_TRUE(st.finished);
  EXPECT_FALSE(st.status & status::busy);
  EXPECT_EQ(st.executor.moves, 2u);
  EXPECT_EQ(st.executor.distance_mismatches, 0u);
  EXPECT_TRUE(rig.board.violations().empty());
}

TEST(LmcBoard, LaserDelaysShiftTheGateWithoutCostingTime) {
  Rig rig;
  rig.arm();
  const auto c = at(0, 0);
  const std::array<std::uint16_t, 2> a{c[0], c[1]}, b{std::uint16_t(c[0] + 300), c[1]},
      d{std::uint16_t(c[0] + 600), c[1]};
  // Mark 300 units at 1 unit/tick (300 ticks), on delay 100 µs, off delay 50 µs, then a jump of
  // 300 ticks. The gate opens at tick 10 of the mark and closes 5 ticks into the jump.
  rig.packet({word(Op::JumpSpeed, 100), word(Op::MarkSpeed, 100), word(Op::LaserOnDelay, 100, 0),
              word(Op::LaserOffDelay, 50, 0), move(Op::MarkTo, a, b), move(Op::JumpTo, b, d),
              word(Op::EndOfList)});
  rig.single(word(Op::ExecuteList));
  rig.board.advance(0.01);
  const auto lit = rig.lit();
  ASSERT_EQ(lit.size(), 600u);
  for (std::size_t i = 0; i < lit.size(); ++i)
    EXPECT_EQ(lit[i], i >= 10 && i < 305) << "tick " << i;
}

TEST(LmcBoard, PolygonDelayScalesWithTheTurnAndJumpDelayHolds) {
  Rig rig;
  rig.arm();
  const auto c = at(0, 0);
  const std::array<std::uint16_t, 2> p0{c[0], c[1]}, p1{std::uint16_t(c[0] + 100), c[1]},
      p2{std::uint16_t(c[0] + 200), c[1]}, p3{std::uint16_t(c[0] + 200), std::uint16_t(c[1] + 100)},
      p4{std::uint16_t(c[0] + 300), std::uint16_t(c[1] + 100)};
  // Straight on (φ = 0): no hold; a right angle: 200 µs × (1 − cos 90°) = 20 ticks, lit. After
  // the last mark a jump with a 300 µs jump delay: 100 ticks moving + 30 holding, dark.
  rig.packet({word(Op::JumpSpeed, 100), word(Op::MarkSpeed, 100), word(Op::PolygonDelay, 20),
              word(Op::JumpDelay, 300, 0), move(Op::MarkTo, p0, p1), move(Op::MarkTo, p1, p2),
              move(Op::MarkTo, p2, p3), move(Op::JumpTo, p3, p4), word(Op::EndOfList)});
  rig.single(word(Op::ExecuteList));
  rig.board.advance(0.01);
  const auto& s = rig.sink.samples;
  ASSERT_EQ(s.size(), 100u + 100u + 20u + 100u + 100u + 30u);
  EXPECT_EQ(rig.count_lit(), 320u);
  // The corner hold: samples 200..219 all at p2.
  for (std::size_t i = 200; i < 220; ++i) {
    EXPECT_FLOAT_EQ(s[i].x_mm, s[199].x_mm) << i;
    EXPECT_FLOAT_EQ(s[i].y_mm, s[199].y_mm) << i;
    EXPECT_TRUE(s[i].laser);
  }
  for (std::size_t i = s.size() - 30; i < s.size(); ++i) EXPECT_FLOAT_EQ(s[i].x_mm, s.back().x_mm);
}

TEST(LmcBoard, DwellsDelaysAndTheGates) {
  Rig rig;
  rig.single(word(Op::EnableLaser));
  rig.single(word(Op::FiberSetMo, 1));
  // The list sets the port itself: dark until WritePort(list) 1, then a 20-tick LaserOnPoint,
  // a 10-tick DelayTime, then the port closed and another LaserOnPoint that stays dark.
  rig.packet({word(Op::LaserOnPoint, 5), word(Op::ListWritePort, 1), word(Op::LaserOnPoint, 20),
              word(Op::DelayTime, 10), word(Op::ListWritePort, 0), word(Op::LaserOnPoint, 7),
              word(Op::EndOfList)});
  rig.single(word(Op::ExecuteList));
  rig.board.advance(0.01);
  const auto lit = rig.lit();
  ASSERT_EQ(lit.size(), 5u + 20u + 10u + 7u);
  for (std::size_t i = 0; i < lit.size(); ++i) EXPECT_EQ(lit[i], i >= 5 && i < 25) << i;

  // The oscillator closed: nothing leaves the board whatever the list says.
  Rig closed;
  closed.single(word(Op::EnableLaser));
  closed.single(word(Op::WritePort, 1));
  closed.packet({word(Op::LaserOnPoint, 20), word(Op::EndOfList)});
  closed.single(word(Op::ExecuteList));
  closed.board.advance(0.01);
  EXPECT_EQ(closed.sink.samples.size(), 20u);
  EXPECT_EQ(closed.count_lit(), 0u);
}

TEST(LmcBoard, ReadyClearsWhenTheBufferIsFullAndAPacketSentAnywayIsLost) {
  BoardOptions o;
  o.list_capacity = 2;
  EmulatedBoard board(o);
  const auto status = [&] {
    board.out(bytes(word(Op::GetVersion)));
    std::array<std::uint8_t, kReplyBytes> r{};
    board.in(r);
    return decode_reply(r).status();
  };
  std::vector<Word> marks(kCommandsPerPacket, word(Op::DelayTime, 1));
  ListPacket p;
  for (const Word& w : marks) p.push(w);
  EXPECT_TRUE(status() & status::ready);
  board.out(p.bytes());
  EXPECT_TRUE(status() & status::ready);
  board.out(p.bytes());
  EXPECT_FALSE(status() & status::ready);
  EXPECT_FALSE(status() & status::busy);
  board.out(p.bytes());  // the host ignored READY
  BoardState s = board.state();
  EXPECT_EQ(s.packets_received, 2u);
  EXPECT_EQ(s.packets_lost, 1u);
  ASSERT_EQ(board.violations().size(), 1u);
  EXPECT_NE(board.violations()[0].find("list packet 3 arrived while READY was clear: lost"),
            std::string::npos);
  // Executing frees the slots: 256 ticks per packet.
  board.out(bytes(word(Op::ExecuteList)));
  std::array<std::uint8_t, kReplyBytes> r{};
  board.in(r);
  EXPECT_TRUE(status() & status::busy);
  board.advance(256 * 10e-6);
  EXPECT_TRUE(status() & status::ready);
  // Two full packets and no EndOfList: after them the board waits — an underrun, gate closed.
  board.advance(0.01);
  s = board.state();
  EXPECT_EQ(s.executor.underrun_events, 1u);
  EXPECT_GT(s.executor.underrun_ticks, 0u);
  EXPECT_TRUE(s.executing);
}

// The wire record's host clock (WireRecord::arrived) is what the station's trigger-to-first-
// sample figure is read against: each transfer stamped between the host's own readings of the
// steady clock before and after it, in order.
TEST(LmcBoard, StampsEachTransferWithTheHostsSteadyClock) {
  using Clock = std::chrono::steady_clock;
  EmulatedBoard board;
  ListPacket p;
  p.push(word(Op::DelayTime, 1));
  std::vector<std::pair<Clock::time_point, Clock::time_point>> windows;
  for (int i = 0; i < 3; ++i) {
    const auto before = Clock::now();
    if (i == 1)
      board.out(p.bytes());
    else
      board.out(bytes(word(i == 0 ? Op::GetVersion : Op::ExecuteList)));
    windows.emplace_back(before, Clock::now());
  }
  const std::vector<WireRecord> wire = board.wire();
  ASSERT_EQ(wire.size(), 3u);
  EXPECT_TRUE(wire[1].packet);
  EXPECT_EQ(wire[2].single.opcode(), static_cast<std::uint16_t>(Op::ExecuteList));
  for (std::size_t i = 0; i < wire.size(); ++i) {
    EXPECT_GE(wire[i].arrived, windows[i].first) << "transfer " << i;
    EXPECT_LE(wire[i].arrived, windows[i].second) << "transfer " << i;
  }
}

TEST(LmcBoard, RecordsWhatTheHostGetsWrong) {
  EmulatedBoard board;
  const std::array<std::uint8_t, 5> odd{};
  EXPECT_EQ(board.out(odd), Urb::stall);
  board.out(bytes(word(Op::JumpTo, 1, 2, 0, 3)));  // a list command sent alone
  ListPacket p;
  p.push(word(Op::GetVersion));         // a single command in a packet
  p.push(Word{{0x8099, 0, 0, 0, 0, 0}});  // unknown
  p.push(word(Op::EndOfList));
  p.push(word(Op::MarkSpeed, 5));       // after the end
  board.out(p.bytes());
  const auto v = board.violations();
  ASSERT_EQ(v.size(), 5u);
  EXPECT_NE(v[0].find("a transfer of 5 bytes"), std::string::npos);
  EXPECT_NE(v[1].find("list command 0x8001 sent alone"), std::string::npos);
  EXPECT_NE(v[2].find("single command 0x0007 in packet 1 slot 0"), std::string::npos);
  EXPECT_NE(v[3].find("unknown list command 0x8099 in packet 1 slot 1"), std::string::npos);
  EXPECT_NE(v[4].find("a command after EndOfList in packet 1 slot 3"), std::string::npos);
}

TEST(LmcBoard, FaultsStallHangAndUnplug) {
  BoardFaults f;
  f.stall_at_packet = 1;
  EmulatedBoard stalled({}, f);
  ListPacket p;
  p.push(word(Op::EndOfList));
  EXPECT_EQ(stalled.out(p.bytes()), Urb::stall);
  EXPECT_EQ(stalled.out(bytes(word(Op::GetVersion))), Urb::stall);  // halted until cleared
  stalled.clear_halt();
  EXPECT_EQ(stalled.out(bytes(word(Op::GetVersion))), Urb::done);

  BoardFaults h;
  h.hang_at_packet = 1;
  h.hang_s = 0.001;
  EmulatedBoard hung({}, h);
  EXPECT_EQ(hung.out(p.bytes()), Urb::pending);
  EXPECT_EQ(hung.out(bytes(word(Op::GetVersion))), Urb::pending);
  hung.advance(0.002);
  EXPECT_EQ(hung.out(bytes(word(Op::GetVersion))), Urb::done);

  BoardFaults u;
  u.unplug_at_packet = 2;
  EmulatedBoard gone({}, u);
  int notified = 0;
  gone.on_unplug = [&] { ++notified; };
  EXPECT_EQ(gone.out(p.bytes()), Urb::done);
  EXPECT_EQ(gone.out(p.bytes()), Urb::no_device);
  EXPECT_EQ(gone.out(bytes(word(Op::GetVersion))), Urb::no_device);
  std::array<std::uint8_t, kReplyBytes> r{};
  EXPECT_EQ(gone.in(r), Urb::no_device);
  EXPECT_EQ(notified, 1);
}

}  // namespace
}  // namespace mark::lmc
