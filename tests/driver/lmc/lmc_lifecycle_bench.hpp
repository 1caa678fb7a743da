#pragma once
// The LMC device in the lifecycle suite (tests/driver/device_lifecycle_suite.hpp): a job is a
// serpentine of short marks, 64 device commands a piece; the laser is seen on the emulated
// board (its laser port bit, its master oscillator, whether it emits) or, for a capture, in the
// last port write on the wire.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <vector>

#include "driver/lmc/emulated_board.hpp"
#include "driver/lmc/lmc_device.hpp"
#include "tests/driver/device_lifecycle_suite.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc::test {

inline constexpr std::size_t kCommandsPerPiece = 64;

// Piece k of an endless serpentine inside ±10 mm: command 0 a jump, every other one a 0.2 mm
// mark (rows of 100, 0.1 mm apart, wrapping after 100 rows). `outside`: one point at x = 60 mm,
// beyond the 110 mm lens.
inline std::vector<DeviceCommand> serpentine_piece(std::size_t k, bool outside = false) {
  std::vector<DeviceCommand> c;
  for (std::size_t i = k * kCommandsPerPiece; i < (k + 1) * kCommandsPerPiece; ++i) {
    if (i == 0) {
      c.push_back(DeviceCommand::jump_to(-10, 0));
      continue;
    }
    const std::size_t row = (i / 100) % 100, col = i % 100;
    const double x = -10 + 0.2 * double(row % 2 ? 100 - col : col);
    c.push_back(DeviceCommand::mark_to(x, -5 + 0.1 * double(row) + ((i % 2) ? 0.05 : 0.0)));
  }
  if (outside) c[kCommandsPerPiece / 2] = DeviceCommand::mark_to(60, 0);
  return c;
}

// What every LMC bench shares: the device, its job, its progress units.
struct LmcBenchBase {
  static constexpr bool kSeesLaserWhileFed = true;  // the wire and the board are thread-safe
  virtual ~LmcBenchBase() = default;
  virtual LmcDevice& lmc() = 0;
  Device& device() { return lmc(); }
  JobHeader header() { return header_with(fast_pen()); }
  void feed(std::size_t k) { lmc().submit(serpentine_piece(k)); }
  void feed_outside(std::size_t k) { lmc().submit(serpentine_piece(k, true)); }
  std::uint64_t units(std::size_t pieces) const { return pieces * kCommandsPerPiece; }
  // A list packet (256 list commands, so at most 256 device commands) may be on the wire when
  // abort() takes the wire lock; its commands count as sent once it is through.
  std::uint64_t stop_bound() const { return kCommandsPerPacket; }
  double half_field_mm() const { return 55; }
};

// The board's view: laser port bit clear, master oscillator closed, nothing emitted.
inline bool board_laser_off(const EmulatedBoard& board) {
  const BoardState s = board.state();
  return (s.port & 0x0001) == 0 && !s.mo_open && !s.laser_emitting;
}

}  // namespace mark::lmc::test
