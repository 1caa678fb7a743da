// Timed moves on the LMC board (look-ahead and feed-forward, driver/device_command.hpp): the
// encoder picks each move's speed word from the distance in board units, so the emulated board
// runs it in the host's ticks; a move that goes nowhere in units is held for its time; a lit
// move's power fraction scales the pen's MarkCurrent.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "driver/lmc/job_encoder.hpp"
#include "tests/driver/lmc/board_rig.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc {
namespace {

// The words of a job of `commands` with the golden pen's laser (100 %, 20 kHz) and no delays.
std::vector<Word> encode_timed(const std::vector<DeviceCommand>& commands, BoardPen* pen_out = nullptr,
                               bool word_ticks = false) {
  const FieldUnits units(110);
  std::vector<Word> words;
  JobEncoder enc(units, [&](const ListPacket& p, const PacketInfo&) {
    for (std::size_t i = 0; i < kCommandsPerPacket; ++i) words.push_back(load(p.bytes().data() + 12 * i));
  });
  DevicePen dp = test::golden_pen();
  dp.laser_on_delay_s = dp.laser_off_delay_s = dp.polygon_delay_s = dp.mark_delay_s = 0;
  const BoardPen pen = encode_pen(dp, 0, units);
  if (pen_out) *pen_out = pen;
  enc.set_word_ticks(word_ticks);
  enc.start_list(0, 1);
  enc.apply_pen(pen);
  for (std::size_t i = 0; i < commands.size(); ++i) enc.add(commands[i], i);
  enc.finish(commands.size());
  return words;
}

// Runs the words on a hand-driven board (plain axes, the output recorded tick by tick).
std::vector<ScanSample> run_on_board(const std::vector<Word>& words, bool word_ticks = false) {
  BoardOptions options = test::Rig::plain();
  options.behaviour.word_ticks = word_ticks;
  test::Rig rig(options);
  rig.arm();
  for (std::size_t at = 0; at < words.size(); at += kCommandsPerPacket) {
    const std::vector<Word> packet(words.begin() + static_cast<std::ptrdiff_t>(at),
                                   words.begin() + static_cast<std::ptrdiff_t>(std::min(words.size(), at + kCommandsPerPacket)));
    EXPECT_EQ(rig.packet(packet), Urb::done);
  }
  rig.single(word(Op::ExecuteList));
  rig.board.advance(0.05);
  EXPECT_TRUE(rig.board.state().finished);
  return rig.sink.samples;
}

// 1 mm lit in 50 ticks at half power; 20 ticks held lit at a quarter; a dark move of 0.8 mm in
// 37 ticks; 2.5 mm lit in 333 ticks (4.47 units a tick: no speed word is exactly that) at full
// power.
std::vector<DeviceCommand> four_moves() {
  using C = DeviceCommand;
  return {C::timed_move(true, 1.0, 0, 2000, 50e-5, 0.5), C::timed_move(true, 1.0, 0, 0, 20e-5, 0.25),
          C::timed_move(false, 1.0, 0.8, 2162, 37e-5), C::timed_move(true, 3.5, 0.8, 751, 333e-5, 1.0)};
}

TEST(LmcTimedMoves, EachMoveTakesItsTicksAtItsPowerAndAStillOneHolds) {
  const std::vector<DeviceCommand> commands = four_moves();
  BoardPen pen;
  const std::vector<Word> words = encode_timed(commands, &pen);
  const std::vector<ScanSample> s = run_on_board(words);
  ASSERT_EQ(s.size(), 50u + 20u + 37u + 333u);
  const double unit_mm = 1 / FieldUnits(110).units_per_mm();
  const auto power_of = [&](double fraction) {
    return static_cast<std::uint8_t>(std::lround(std::lround(pen.power * fraction) / 4095.0 * 255.0));
  };
  for (std::size_t k = 0; k < 50; ++k) {
    EXPECT_TRUE(s[k].laser) << k;
    EXPECT_EQ(s[k].power, power_of(0.5)) << k;
    // On the evenly timed straight move, within two field units: the target truncated to a
    // unit, each tick's point rounded to one.
    EXPECT_NEAR(s[k].x_mm, 1.0 * double(k + 1) / 50, 2 * unit_mm) << k;
  }
  for (std::size_t k = 50; k < 70; ++k) {
    EXPECT_TRUE(s[k].laser) << k;
    EXPECT_EQ(s[k].power, power_of(0.25)) << k;
    EXPECT_NEAR(s[k].x_mm, 1.0, unit_mm) << k;
  }
  for (std::size_t k = 70; k < 107; ++k) EXPECT_FALSE(s[k].laser) << k;
  EXPECT_NEAR(s[106].y_mm, 0.8, unit_mm);
  for (std::size_t k = 107; k < s.size(); ++k) {
    EXPECT_TRUE(s[k].laser) << k;
    EXPECT_EQ(s[k].power, power_of(1.0)) << k;
  }
  EXPECT_NEAR(s.back().x_mm, 3.5, unit_mm);
  // The dark move set its own jump speed and no jump delay; the hold is a LaserOnPoint.
  bool held = false, jump_delay_zero = false;
  for (const Word& w : words) {
    held |= w == word(Op::LaserOnPoint, 20);
    jump_delay_zero |= w == word(Op::JumpDelay, 0, 0);
  }
  EXPECT_TRUE(held);
  EXPECT_TRUE(jump_delay_zero);
}

// A board whose every word but a move takes a tick (the emulated word_ticks): told so, the
// encoder gives each timed move back the ticks of the words since the move before (its power,
// speed and delay words; the hold's own word), so from the first move on every move ends on the
// host's tick as on a plain board. Not told, each later move ends a tick late per word.
TEST(LmcTimedMoves, OnABoardWhoseWordsTakeATickEachMoveGivesTheirTicksBack) {
  const std::vector<DeviceCommand> commands = four_moves();
  const double unit_mm = 1 / FieldUnits(110).units_per_mm();
  // The ticks the moves end on, counted from the first lit tick: where the first reaches x = 1,
  // where the dark one reaches y = 0.8, the last sample. (A word's own tick holds the mirrors.)
  const auto ends = [&](const std::vector<ScanSample>& s) {
    std::size_t first = 0;
    while (first < s.size() && !s[first].laser) ++first;
    std::size_t at_x = first, at_y = first;
    while (at_x < s.size() && s[at_x].x_mm < 1.0 - unit_mm) ++at_x;
    while (at_y < s.size() && s[at_y].y_mm < 0.8 - unit_mm) ++at_y;
    return std::vector<std::size_t>{at_x + 1 - first, at_y + 1 - first, s.size() - first};
  };
  const std::vector<ScanSample> plain = run_on_board(encode_timed(commands));
  const std::vector<ScanSample> told = run_on_board(encode_timed(commands, nullptr, true), true);
  const std::vector<ScanSample> untold = run_on_board(encode_timed(commands), true);
  // Plain: the first move ends at 50, the hold to 70, the dark move at 107, the last at 440.
  EXPECT_EQ(ends(plain), (std::vector<std::size_t>{50, 107, 440}));
  EXPECT_EQ(ends(told), ends(plain));
  EXPECT_NEAR(told.back().x_mm, 3.5, unit_mm);
  // Untold: the dark move ends 3 ticks late (the hold's power word, the hold's own word, the
  // jump speed; the pen's jump delay is already 0), the last move 5 (its power and speed words).
  EXPECT_EQ(ends(untold), (std::vector<std::size_t>{50, 110, 445}));
}

TEST(LmcTimedMoves, ASlowShortMoveTakesNoMoreThanItsTicks) {
  // 3 units in 100 ticks: the speed word's step (1/100 unit a tick) cannot say it exactly; the
  // smallest word that is not late (3 units per ms, 1 tick each 0.03 unit) takes 100 ticks.
  // 2 units in 300 ticks: no word is slow enough (1 is 0.01 unit a tick): 200 ticks, shorter,
  // never longer — the board is never behind the host's clock.
  const double unit_mm = 1 / FieldUnits(110).units_per_mm();
  const std::vector<DeviceCommand> commands = {DeviceCommand::timed_move(true, 3 * unit_mm, 0, 1, 100e-5),
                                               DeviceCommand::timed_move(true, 5 * unit_mm, 0, 1, 300e-5)};
  const std::vector<ScanSample> s = run_on_board(encode_timed(commands));
  EXPECT_EQ(s.size(), 100u + 200u);
}

TEST(LmcTimedMoves, AMoveFasterThanAnyWordIsRefusedNamingIt) {
  // 100 mm in one tick: 5.96 million units per ms.
  try {
    encode_timed({DeviceCommand::timed_move(true, 50, 0, 1e7, 1e-5)});
    FAIL() << "not refused";
  } catch (const EncodeError& e) {
    EXPECT_NE(std::string(e.what()).find("mark speed"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mark::lmc
