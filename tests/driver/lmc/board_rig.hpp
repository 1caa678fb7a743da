#pragma once
// A hand-driven emulated board for the board's own tests: single commands and packets in, the
// clock stepped by hand, every tick's sample recorded — so every figure is exact.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "driver/lmc/emulated_board.hpp"
#include "tests/ringbuffer/recording_sink.hpp"

namespace mark::lmc::test {

using Sink = mark::test::RecordingSink<ScanSample>;

// A board with its output recorded, driven by hand: singles and packets in, ticks out.
struct Rig {
  Rig() : board(options()) {}
  explicit Rig(BoardOptions o) : board(with_sink(o)) {}
  // The words below are built with FieldUnits(110): the plain axes, PolygonDelay in 10 µs.
  BoardOptions options() { return with_sink(plain()); }
  static BoardOptions plain() {
    BoardOptions o;
    o.axes = AxisMap{};
    o.polygon_delay_unit = PolygonDelayUnit::ten_us;
    return o;
  }
  BoardOptions with_sink(BoardOptions o) {
    o.scanner = &sink;
    return o;
  }
  Reply single(const Word& w) {
    EXPECT_EQ(board.out(bytes(w)), Urb::done);
    std::array<std::uint8_t, kReplyBytes> r{};
    if (find_command(w.opcode())->reply) {
      EXPECT_EQ(board.in(r), Urb::done);
    }
    return decode_reply(r);
  }
  Urb packet(const std::vector<Word>& words) {
    ListPacket p;
    for (const Word& w : words) p.push(w);
    return board.out(p.bytes());
  }
  // Laser enabled, port bit 0, oscillator open; jump 100 units/ms (1 unit per tick), mark 50.
  void arm() {
    single(word(Op::EnableLaser));
    single(word(Op::WritePort, 1));
    single(word(Op::FiberSetMo, 1));
  }
  std::vector<bool> lit() const {
    std::vector<bool> out;
    for (const ScanSample& s : sink.samples) out.push_back(s.laser);
    return out;
  }
  std::size_t count_lit() const {
    std::size_t n = 0;
    for (const ScanSample& s : sink.samples) n += s.laser;
    return n;
  }
  Sink sink;
  EmulatedBoard board;
};

// Field units of a 110 mm lens: 1 mm = 595.77 units.
inline std::array<std::uint16_t, 2> at(double x, double y) { return FieldUnits(110).point(x, y); }

inline Word move(Op op, std::array<std::uint16_t, 2> from, std::array<std::uint16_t, 2> to) {
  return word(op, to[0], to[1], 0, segment_distance(from, to));
}

}  // namespace mark::lmc::test
