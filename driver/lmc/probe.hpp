#pragma once
// `marker lmc probe`: the first contact with a board, and what settles what docs/lmc.md lists as
// not verified. It reads the board's serial and version, then times lists the board executes —
// with the laser masked off for the whole probe (masked_link.hpp: no transfer that could enable
// the laser leaves the host), the red pointer tracing the moves — and compares each against the
// readings the open drivers leave open:
//
// - the jump delay the board holds before any list set one (power-on, or another program's);
// - PolygonDelay's unit (a word of 300 at right angles: 300 µs or 3 ms per corner) and whether
//   the board scales it by the turn (straight-on segments get none);
// - whether a JumpTo after a mark run waits out the laser-off delay;
// - how many packets the board buffers before READY clears (before ExecuteList);
// - what DelayTime and a parameter word cost beyond their own time (a tick each, or nothing);
// - how moves are rounded to ticks (whole ticks each, rounded up; the exact time; nearest);
// - how long a list of moves really takes against the host's estimate (what the session's
//   deadline follows).
//
// Every measurement is the difference of two lists that differ in one thing only, so the host's
// own latency (ExecuteList → the poll that sees BUSY clear) cancels; each difference is tens to
// hundreds of milliseconds, far above a poll interval of 1 ms.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "driver/laser_source.hpp"
#include "driver/lmc/codec.hpp"
#include "driver/lmc/link.hpp"
#include "driver/lmc/session.hpp"

namespace mark::lmc {

struct ProbeOptions {
  double field_mm = 110;
  AxisMap axes = kEzCadAxes;
  int laser_bit = 0;  // masked off: never set
  int red_bit = 8;    // the red pointer traces the probe's moves
  LaserSource source = LaserSource::fiber;  // whose words the timed list of moves carries (at 0 %)
  PolygonDelayUnit polygon_delay_unit = PolygonDelayUnit::signed_us;  // for that list's estimate
  InitParams init;
};

// One list the probe timed.
struct ProbeList {
  std::string name;
  std::size_t words = 0;
  double measured_s = 0;  // ExecuteList → not BUSY, as the host saw it
};

struct ProbeReport {
  std::string link;
  BoardIdentity identity;
  double latency_s = 0;                // an empty list: what the host's measurement adds
  double held_jump_delay_us = 0;       // per JumpTo, before any JumpDelay was sent
  int polygon_word = 0;                // the PolygonDelay word the probe sent
  double polygon_corner_us = 0;        // per right angle, with that word
  double polygon_straight_us = 0;      // per straight-on junction, the same word
  std::string polygon_unit;            // "us", "10us" or "unclear"
  std::optional<bool> polygon_scaled;  // by (1 − cos φ); nullopt: unclear
  double off_delay_wait_us = 0;        // per JumpTo after a mark, laser-off delay 2000 µs
  bool jump_waits = false;
  std::size_t buffered_packets = 0;    // accepted before READY cleared (capped at kMaxPackets)
  bool buffered_capped = false;
  double delay_time_extra_us = 0;      // per DelayTime word beyond its own 10 µs × k
  bool delay_time_extra_tick = false;
  double parameter_word_us = 0;        // per parameter word
  bool parameter_word_tick = false;
  double move_ticks_exact = 0;         // the probe's moves' exact length in ticks
  double move_ticks_measured = 0;      // what each took
  std::string move_rounding;           // "whole (up)", "exact", "nearest" or "unclear"
  std::size_t list_moves = 0;          // the representative list
  double list_estimated_s = 0;
  double list_measured_s = 0;
  std::vector<ProbeList> lists;
  std::vector<std::string> conclusions;  // one line each, what a user with this board should set
  std::string polygon_units_option;      // the --polygon-delay-units value the board wants
};

inline constexpr std::size_t kMaxProbePackets = 64;
// Below this a held jump delay is the measurement's noise (the median of three lists of 800
// jumps, each list's timing to a few milliseconds under load).
inline constexpr double kHeldJumpDelayNoise_us = 30;

// Runs the probe on the board behind `link` (its init sequence included). `progress` gets a line
// per list. Throws DeviceError if the board does not answer.
ProbeReport probe_board(LmcLink& link, const ProbeOptions& options,
                        const std::function<void(const std::string&)>& progress = {});

}  // namespace mark::lmc
