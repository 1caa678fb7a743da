#pragma once
// Shared pieces of the LMC tests: the golden rectangle of galvo.md §1.9 (meerk40t's test
// vector), its pen, and a bench of emulated board + LmcDevice over the loopback link.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "driver/lmc/codec.hpp"
#include "driver/lmc/emulated_board.hpp"
#include "driver/lmc/lmc_device.hpp"
#include "driver/lmc/loopback_link.hpp"

namespace mark::lmc::test {

// meerk40t test/test_drivers_galvo.py `lmc_rect` (meerk40t@5f68a45b), word for word: "rect 2cm
// 2cm 1cm 1cm engrave -s 15" on meerk40t's default galvo device (110 mm lens, swap_xy + flip_y
// on its y-down scene: EzCad's axes).
inline std::vector<Word> meerk40t_rectangle_words() {
  return {
      word(Op::ReadyMark),
      word(Op::DelayTime, 0x0320),
      word(Op::ListWritePort, 0x0001),
      word(Op::JumpSpeed, 0x04A7),
      word(Op::QSwitchPeriod, 0x03E8),
      word(Op::MarkCurrent, 0x0FFF),
      word(Op::MarkSpeed, 0x0008),
      word(Op::LaserOnDelay, 0x0064),
      word(Op::LaserOffDelay, 0x0064),
      word(Op::PolygonDelay, 0x000A),
      word(Op::JumpTo, 0xD174, 0x2E8B, 0x0000, 0x7331),
      word(Op::MarkTo, 0xD174, 0x45D1, 0x0000, 0x1746),
      word(Op::MarkTo, 0xBA2E, 0x45D1, 0x0000, 0x1746),
      word(Op::MarkTo, 0xBA2E, 0x2E8B, 0x0000, 0x1746),
      word(Op::MarkTo, 0xD174, 0x2E8B, 0x0000, 0x1746),
      word(Op::DelayTime, 0x001E),
      word(Op::EndOfList),
  };
}

// What this driver sends for it: the same words and one more, JumpDelay(0) before the jump.
// Every list sets every delay; meerk40t sends no JumpDelay for a jump delay of 0 and takes the
// board's, whatever an earlier program left there.
inline std::vector<Word> golden_rectangle_words() {
  std::vector<Word> w = meerk40t_rectangle_words();
  w.insert(w.begin() + 10, word(Op::JumpDelay, 0, 0));
  return w;
}

// meerk40t's units for it: EzCad's axes, PolygonDelay in 10 µs (meerk40t since 2025).
inline FieldUnits golden_units() { return FieldUnits(110, kEzCadAxes, PolygonDelayUnit::ten_us); }

// The init sequence of galvo.md §1.8 as the driver sends it (with WritePort(0) after Reset and
// no correction table).
inline std::vector<Word> expected_init() {
  return {word(Op::GetSerialNo), word(Op::GetVersion), word(Op::Reset), word(Op::WritePort, 0),
          word(Op::WriteCorTable, 0), word(Op::EnableLaser), word(Op::SetControlMode, 0),
          word(Op::SetLaserMode, 1), word(Op::SetDelayMode, 1), word(Op::SetTiming, 1),
          word(Op::SetStandby, 2000, 20), word(Op::SetFirstPulseKiller, 200),
          word(Op::SetPwmHalfPeriod, 125), word(Op::SetPwmPulseWidth, 125), word(Op::FiberSetMo, 0),
          word(Op::SetFpkParam2, 0xFFB, 1, 409, 100), word(Op::SetFlyRes, 0, 99, 1000, 25),
          word(Op::EnableZ), word(Op::WriteAnalogPort1, 0x7FF), word(Op::EnableZ)};
}

// The parameters behind it: meerk40t's defaults (galvo.md §1.9) with the test's 15 mm/s mark
// speed, 100 % power and 20 kHz; a 110 mm lens.
inline DevicePen golden_pen() {
  DevicePen p;
  p.mark_speed_mm_s = 15;
  p.jump_speed_mm_s = 2000;
  p.laser_on_delay_s = 100e-6;
  p.laser_off_delay_s = 100e-6;
  p.polygon_delay_s = 100e-6;
  p.mark_delay_s = 300e-6;  // meerk40t's "end delay"
  p.jump_delay_s = 0;
  p.laser.power_pct = 100;
  p.laser.frequency_khz = 20;
  return p;
}

// The rectangle itself in the field frame (x right, y up, origin at the centre): meerk40t's
// scene rectangle (20, 20)–(30, 30) mm on its 110 mm lens, whose y points down from the top
// left: x = sx − 55, y = 55 − sy.
inline std::vector<DeviceCommand> golden_rectangle_commands() {
  return {DeviceCommand::jump_to(-35, 35), DeviceCommand::mark_to(-25, 35),
          DeviceCommand::mark_to(-25, 25), DeviceCommand::mark_to(-35, 25),
          DeviceCommand::mark_to(-35, 35)};
}

inline std::vector<std::uint8_t> packet_bytes(const std::vector<Word>& words) {
  ListPacket p;
  for (const Word& w : words) p.push(w);
  return {p.bytes().begin(), p.bytes().end()};
}

inline LmcOptions quick_options() {
  LmcOptions o;
  o.init.settle_s = 0;  // the 50 ms settle sleep only slows the tests down
  return o;
}

// The same with meerk40t's polygon-delay unit, for the golden words.
inline LmcOptions golden_options() {
  LmcOptions o = quick_options();
  o.polygon_delay_unit = PolygonDelayUnit::ten_us;
  return o;
}

// An emulated board that reads PolygonDelay as the golden words mean it.
inline BoardOptions golden_board() {
  BoardOptions o;
  o.polygon_delay_unit = PolygonDelayUnit::ten_us;
  return o;
}

inline JobHeader header_with(DevicePen pen, double field_mm = 110) {
  JobHeader h;
  h.name = "test";
  h.field_mm = field_mm;
  h.pens = {pen};
  return h;
}

// An emulated board on its own clock (time_scale × real time) and an LmcDevice on it.
struct LoopbackBench {
  explicit LoopbackBench(BoardOptions board_options = {}, BoardFaults faults = {},
                         LmcOptions options = quick_options(), double time_scale = 1.0)
      : board(board_options, faults) {
    board.start_clock(time_scale);
    device = std::make_unique<LmcDevice>(std::make_unique<LoopbackLink>(board), options);
  }
  ~LoopbackBench() {
    device.reset();
    board.stop_clock();
  }
  EmulatedBoard board;
  std::unique_ptr<LmcDevice> device;
};

// A serpentine of n short marks (0.2 mm, rows of 100) after one jump: at 2000 mm/s each
// takes 0.1 ms, so a packet of 256 lasts about 26 ms on the board.
inline std::vector<DeviceCommand> zigzag(std::size_t n) {
  std::vector<DeviceCommand> c{DeviceCommand::jump_to(-10, 0)};
  for (std::size_t i = 1; i <= n; ++i) {
    const std::size_t row = i / 100, col = i % 100;
    const double x = -10 + 0.2 * double(row % 2 ? 100 - col : col);
    c.push_back(DeviceCommand::mark_to(x, 0.1 * double(row) + ((i % 2) ? 0.05 : 0.0)));
  }
  return c;
}

inline DevicePen fast_pen() {
  DevicePen p = golden_pen();
  p.mark_speed_mm_s = 2000;
  p.jump_speed_mm_s = 4000;
  return p;
}

inline double figure(const DeviceReport& r, const std::string& key) {
  for (const auto& [k, v] : r.figures)
    if (k == key) return v;
  return -1;
}

// Every single command the board received, in order.
inline std::vector<Word> singles(const std::vector<WireRecord>& wire) {
  std::vector<Word> out;
  for (const WireRecord& r : wire)
    if (!r.packet) out.push_back(r.single);
  return out;
}

}  // namespace mark::lmc::test
