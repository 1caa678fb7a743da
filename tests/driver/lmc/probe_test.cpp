// `marker lmc probe` against the emulated board in every behaviour variant, in real time: its
// conclusions must be the variant's own settings (read from the variant's BoardOptions, not
// restated), and nothing it sends can fire the laser (the masked link refuses it, the board
// never sees the laser bit).
#include <gtest/gtest.h>

#include <cstdio>

#include "driver/lmc/emulated_link.hpp"
#include "driver/lmc/masked_link.hpp"
#include "driver/lmc/probe.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc {
namespace {

class LmcProbe : public ::testing::TestWithParam<BoardVariant> {};

TEST_P(LmcProbe, ItsConclusionsAreTheVariantsOwn) {
  const BoardVariant v = GetParam();
  const BoardOptions want = with_variant({}, v.name);
  EmulatedLink link({}, std::string(v.name));
  ProbeOptions o;
  o.init.settle_s = 0;
  const ProbeReport r = probe_board(link, o);
  std::printf("%s:\n", std::string(v.name).c_str());
  for (const std::string& line : r.conclusions) std::printf("  %s\n", line.c_str());

  EXPECT_EQ(r.identity.serial, "4C4D4301");
  EXPECT_EQ(r.polygon_unit, want.polygon_delay_unit == PolygonDelayUnit::ten_us ? "10us" : "us");
  EXPECT_EQ(r.polygon_units_option, want.polygon_delay_unit == PolygonDelayUnit::ten_us ? "10us" : "us");
  ASSERT_TRUE(r.polygon_scaled);
  EXPECT_TRUE(*r.polygon_scaled);  // the emulated board scales by 1 − cos φ
  EXPECT_EQ(r.jump_waits, want.behaviour.jump_waits_off_delay);
  EXPECT_EQ(r.buffered_packets, want.list_capacity);
  EXPECT_FALSE(r.buffered_capped);
  EXPECT_EQ(r.delay_time_extra_tick, want.behaviour.word_ticks);
  EXPECT_EQ(r.parameter_word_tick, want.behaviour.word_ticks);
  EXPECT_EQ(r.move_rounding, want.behaviour.exact_move_time ? "exact" : "whole (up)");
  // The foreign registers' jump delay is 500 µs (ExecutorBehaviour::foreign_settings).
  EXPECT_NEAR(r.held_jump_delay_us, want.behaviour.foreign_settings ? 500 : 0, 50);
  // The job's list: never faster than the estimate (less the host's latency, itself measured
  // to a few milliseconds), and within the deadline's margin.
  EXPECT_GE(r.list_measured_s, 0.9 * r.list_estimated_s);
  EXPECT_LE(r.list_measured_s, 2.0 * r.list_estimated_s);

  // Nothing lit, and the laser bit never reached the board.
  const BoardState s = link.board().state();
  EXPECT_EQ(s.executor.lit_ticks, 0u);
  EXPECT_FALSE(s.laser_enabled);
  for (const WireRecord& w : link.board().wire())
    if (!w.packet) {
      EXPECT_FALSE(w.single.opcode() == std::uint16_t(Op::WritePort) && (w.single.p(1) & 1)) << "WritePort with the laser bit";
    }
  for (const auto& packet : link.board().packets())
    for (const Word& w : packet) {
      EXPECT_FALSE(w.opcode() == std::uint16_t(Op::ListWritePort) && (w.p(1) & 1)) << "WritePort(list) with the laser bit";
    }
  EXPECT_FALSE(link.board().red_path().empty());  // the red pointer traced it
  for (const std::string& e : link.board().violations()) ADD_FAILURE() << e;
}

INSTANTIATE_TEST_SUITE_P(EveryBoardVariant, LmcProbe, ::testing::ValuesIn(board_variants().begin(), board_variants().end()),
                         [](const ::testing::TestParamInfo<BoardVariant>& i) { return std::string(i.param.name); });

// The masked link refuses, before a byte goes out, whatever could let light out.
TEST(LmcMaskedLink, RefusesEveryWordThatCouldFire) {
  EmulatedBoard board;
  LoopbackLink loop(board);
  MaskedLink masked(loop, 0);
  const auto refused = [&](const Word& w) {
    try {
      masked.write(bytes(w));
    } catch (const LinkError& e) {
      EXPECT_NE(std::string(e.what()).find("the laser is masked off"), std::string::npos);
      return true;
    }
    masked.read();
    return false;
  };
  EXPECT_TRUE(refused(word(Op::WritePort, 0x0001)));
  EXPECT_TRUE(refused(word(Op::WritePort, 0x0101)));
  EXPECT_FALSE(refused(word(Op::WritePort, 0x0100)));  // the red pointer alone
  EXPECT_TRUE(refused(word(Op::FiberSetMo, 1)));
  EXPECT_FALSE(refused(word(Op::FiberSetMo, 0)));
  EXPECT_TRUE(refused(word(Op::EnableLaser)));
  EXPECT_TRUE(refused(word(Op::LaserSignalOn)));
  ListPacket p;
  p.push(word(Op::ReadyMark));
  p.push(word(Op::ListWritePort, 0x0001));
  EXPECT_THROW(masked.write(p.bytes()), LinkError);
  ListPacket q;
  q.push(word(Op::LaserOnPoint, 10));
  EXPECT_THROW(masked.write(q.bytes()), LinkError);
  EXPECT_EQ(masked.refused(), 7u);
  EXPECT_EQ(board.state().packets_received, 0u);
  for (const WireRecord& w : board.wire()) EXPECT_NE(w.single.opcode(), std::uint16_t(Op::EnableLaser));
}

}  // namespace
}  // namespace mark::lmc
