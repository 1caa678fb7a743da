// The emulated board's behaviour variants, one by one, each against the reference reading with
// the clock stepped by hand (exact tick counts): exact move times, a tick per word, a JumpTo that
// waits out the laser-off delay, foreign registers, the polygon delay's unit; the laser words of
// each source; single commands answered wrongly (stall, no answer, hang, unplug).
#include <gtest/gtest.h>

#include <cctype>
#include <set>

#include "tests/driver/lmc/board_rig.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc {
namespace {

using test::at;
using test::move;
using test::Rig;

BoardOptions variant(std::string_view name) { return with_variant(Rig::plain(), name); }

// A 250-unit jump at 80 units/ms (0.8 units a tick) is 312.5 ticks.
std::vector<Word> four_jumps() {
  const auto c = at(0, 0);
  std::vector<Word> w{word(Op::JumpSpeed, 80), word(Op::JumpDelay, 0, 0)};
  std::array<std::uint16_t, 2> p{c[0], c[1]};
  for (int i = 0; i < 4; ++i) {
    const std::array<std::uint16_t, 2> q{std::uint16_t(p[0] + 250), p[1]};
    w.push_back(move(Op::JumpTo, p, q));
    p = q;
  }
  w.push_back(word(Op::EndOfList));
  return w;
}

std::size_t run(Rig& rig, const std::vector<Word>& words) {
  rig.packet(words);
  rig.single(word(Op::ExecuteList));
  rig.board.advance(0.1);
  EXPECT_TRUE(rig.board.state().finished);
  return rig.sink.samples.size();
}

TEST(LmcBoardVariant, WholeTicksPerMoveOrTheExactTime) {
  Rig whole, exact(variant("exact_ticks"));
  EXPECT_EQ(run(whole, four_jumps()), 4u * 313u);
  EXPECT_EQ(run(exact, four_jumps()), 1250u);
  // Both land on the target.
  EXPECT_FLOAT_EQ(whole.sink.samples.back().x_mm, exact.sink.samples.back().x_mm);
}

TEST(LmcBoardVariant, WordTicksCostATickForEveryWordButMoves) {
  const std::vector<Word> words{word(Op::MarkSpeed, 10), word(Op::MarkSpeed, 20), word(Op::LaserOnDelay, 5, 0),
                                word(Op::DelayTime, 7), word(Op::ListWritePort, 0), word(Op::EndOfList)};
  Rig plain, ticks(variant("word_ticks"));
  EXPECT_EQ(run(plain, words), 7u);  // the DelayTime alone
  EXPECT_EQ(run(ticks, words), 7u + 5u);
}

TEST(LmcBoardVariant, AJumpThatWaitsOutTheLaserOffDelay) {
  const auto c = at(0, 0);
  const std::array<std::uint16_t, 2> a{c[0], c[1]}, b{std::uint16_t(c[0] + 100), c[1]},
      d{std::uint16_t(c[0] + 200), c[1]};
  // A 100-tick mark, 50 µs off delay, a 100-tick jump.
  const std::vector<Word> words{word(Op::JumpSpeed, 100), word(Op::MarkSpeed, 100), word(Op::JumpDelay, 0, 0),
                                word(Op::LaserOnDelay, 0, 0), word(Op::LaserOffDelay, 50, 0),
                                move(Op::MarkTo, a, b), move(Op::JumpTo, b, d), word(Op::EndOfList)};
  Rig plain, waits(variant("jump_waits"));
  plain.arm();
  waits.arm();
  ASSERT_EQ(run(plain, words), 200u);
  ASSERT_EQ(run(waits, words), 205u);
  // Lit the same 105 ticks; the waiting board holds at the mark's end while the gate is open.
  EXPECT_EQ(plain.count_lit(), 105u);
  EXPECT_EQ(waits.count_lit(), 105u);
  for (std::size_t i = 100; i < 105; ++i) {
    EXPECT_FLOAT_EQ(waits.sink.samples[i].x_mm, waits.sink.samples[99].x_mm) << i;
    EXPECT_GT(plain.sink.samples[i].x_mm, plain.sink.samples[99].x_mm) << i;  // already jumping
  }
}

TEST(LmcBoardVariant, ForeignRegistersHoldUntilTheListSetsThem) {
  const auto c = at(0, 0);
  const std::array<std::uint16_t, 2> a{c[0], c[1]}, b{std::uint16_t(c[0] + 100), c[1]};
  const std::vector<Word> unset{word(Op::JumpSpeed, 100), move(Op::JumpTo, a, b), word(Op::EndOfList)};
  const std::vector<Word> set{word(Op::JumpSpeed, 100), word(Op::JumpDelay, 0, 0), move(Op::JumpTo, a, b),
                              word(Op::EndOfList)};
  Rig clean, foreign(variant("foreign_settings")), foreign_set(variant("foreign_settings"));
  EXPECT_EQ(run(clean, unset), 100u);
  EXPECT_EQ(run(foreign, unset), 100u + 50u);  // the 500 µs jump delay another program left
  EXPECT_EQ(run(foreign_set, set), 100u);
}

TEST(LmcBoardVariant, PolygonDelayInTheBoardsUnit) {
  const auto c = at(0, 0);
  const std::array<std::uint16_t, 2> p0{c[0], c[1]}, p1{std::uint16_t(c[0] + 100), c[1]},
      p2{std::uint16_t(c[0] + 100), std::uint16_t(c[1] + 100)};
  // One right angle with PolygonDelay word 100: 100 µs (10 ticks) read in µs, 1 ms (100 ticks)
  // in 10 µs units.
  const std::vector<Word> words{word(Op::MarkSpeed, 100), word(Op::PolygonDelay, 100, 0), move(Op::MarkTo, p0, p1),
                                move(Op::MarkTo, p1, p2), word(Op::EndOfList)};
  BoardOptions us = Rig::plain();
  us.polygon_delay_unit = PolygonDelayUnit::signed_us;
  Rig ten(variant("polygon_10us")), micro(us);
  EXPECT_EQ(run(ten, words), 200u + 100u);
  EXPECT_EQ(run(micro, words), 200u + 10u);
}

TEST(LmcBoardVariant, EveryVariantHasItsOwnName) {
  std::set<std::string_view> names;
  for (const BoardVariant& v : board_variants()) {
    EXPECT_TRUE(names.insert(v.name).second) << v.name;
    EXPECT_FALSE(v.what.empty()) << v.name;
    for (char ch : v.name) EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_') << v.name;
  }
  EXPECT_GE(names.size(), 8u);
  try {
    with_variant({}, "fast");
    FAIL();
  } catch (const DeviceError& e) {
    EXPECT_NE(std::string(e.what()).find("no behaviour variant 'fast' (known: reference, exact_ticks"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(with_variant({}, "shallow_buffer").list_capacity, 2u);
  EXPECT_EQ(with_variant({}, "deep_buffer").list_capacity, 16u);
}

// A CO2 board: no master oscillator to open, the light's power is MarkPowerRatio over twice the
// MarkFreq period (the PWM duty); a fiber's word on it is recorded as a violation.
TEST(LmcBoardSource, EachSourceSetsItsPowerFromItsOwnWords) {
  BoardOptions o = Rig::plain();
  o.behaviour.source = LaserSource::co2;
  Rig co2(o);
  co2.single(word(Op::EnableLaser));
  co2.single(word(Op::WritePort, 1));
  // 20 kHz (period 500 × 100 ns), 60 % (600 × 50 ns high), then a 20-tick dot.
  run(co2, {word(Op::MarkFreq, 500), word(Op::SetCo2Fpk, 100, 100), word(Op::MarkPowerRatio, 600),
            word(Op::LaserOnPoint, 20), word(Op::EndOfList)});
  EXPECT_EQ(co2.count_lit(), 20u);
  EXPECT_EQ(co2.sink.samples.back().power, 153);  // 0.6 × 255
  BoardState s = co2.board.state();
  EXPECT_DOUBLE_EQ(s.executor.power_fraction, 0.6);
  EXPECT_DOUBLE_EQ(s.executor.frequency_khz, 20);
  EXPECT_TRUE(co2.board.violations().empty());

  Rig wrong(o);
  wrong.packet({word(Op::QSwitchPeriod, 1000), word(Op::EndOfList)});
  ASSERT_EQ(wrong.board.violations().size(), 1u);
  EXPECT_NE(wrong.board.violations()[0].find("QSwitchPeriod in packet 1 slot 0 on a board driving a co2 source"),
            std::string::npos)
      << wrong.board.violations()[0];

  // A fiber board: MarkCurrent, and nothing without the oscillator open.
  Rig fiber;
  fiber.single(word(Op::EnableLaser));
  fiber.single(word(Op::WritePort, 1));
  run(fiber, {word(Op::QSwitchPeriod, 1000), word(Op::MarkCurrent, 2457), word(Op::LaserOnPoint, 20),
              word(Op::EndOfList)});
  EXPECT_EQ(fiber.count_lit(), 0u);
  s = fiber.board.state();
  EXPECT_NEAR(s.executor.power_fraction, 0.6, 1e-9);
  EXPECT_DOUBLE_EQ(s.executor.frequency_khz, 20);
  Rig mopa_word;
  mopa_word.packet({word(Op::FiberYLPMPulseWidth, 50), word(Op::EndOfList)});
  ASSERT_EQ(mopa_word.board.violations().size(), 1u);  // a Q-switched fiber has no pulse width
}

TEST(LmcBoard, SingleCommandsAnsweredWrongly) {
  const auto board_with = [](SingleFault::Kind kind) {
    BoardFaults f;
    f.single = SingleFault{static_cast<std::uint16_t>(Op::StopExecute), 2, kind};
    return f;
  };
  std::array<std::uint8_t, kReplyBytes> r{};
  {
    EmulatedBoard b({}, board_with(SingleFault::Kind::no_answer));
    EXPECT_EQ(b.out(bytes(word(Op::StopExecute))), Urb::done);  // the first: answered
    EXPECT_EQ(b.in(r), Urb::done);
    EXPECT_EQ(b.out(bytes(word(Op::StopExecute))), Urb::done);  // the second: taken, no answer
    EXPECT_EQ(b.in(r), Urb::pending);
    EXPECT_EQ(b.out(bytes(word(Op::GetVersion))), Urb::done);   // the next is answered again
    EXPECT_EQ(b.in(r), Urb::done);
    EXPECT_EQ(test::singles(b.wire()).size(), 3u);
  }
  {
    EmulatedBoard b({}, board_with(SingleFault::Kind::stall));
    b.out(bytes(word(Op::StopExecute)));
    b.in(r);
    EXPECT_EQ(b.out(bytes(word(Op::StopExecute))), Urb::stall);
    EXPECT_EQ(b.out(bytes(word(Op::GetVersion))), Urb::stall);  // until the halt is cleared
    b.clear_halt();
    EXPECT_EQ(b.out(bytes(word(Op::StopExecute))), Urb::done);  // written again: taken
    EXPECT_EQ(b.in(r), Urb::done);
  }
  {
    EmulatedBoard b({}, board_with(SingleFault::Kind::hang));
    b.out(bytes(word(Op::StopExecute)));
    b.in(r);
    EXPECT_EQ(b.out(bytes(word(Op::StopExecute))), Urb::pending);
    b.advance(0.06);
    EXPECT_EQ(b.out(bytes(word(Op::GetVersion))), Urb::done);
  }
  {
    EmulatedBoard b({}, board_with(SingleFault::Kind::unplug));
    int notified = 0;
    b.on_unplug = [&] { ++notified; };
    b.out(bytes(word(Op::StopExecute)));
    b.in(r);
    EXPECT_EQ(b.out(bytes(word(Op::StopExecute))), Urb::no_device);
    EXPECT_EQ(b.out(bytes(word(Op::GetVersion))), Urb::no_device);
    EXPECT_EQ(notified, 1);
  }
}

}  // namespace
}  // namespace mark::lmc
