#pragma once
// Device commands → LMC list commands → 3072-byte packets, with no I/O: the part of the driver
// the encoding benchmark measures and the golden-rectangle test checks byte for byte.
//
// Every list starts with a preamble that sets everything its marks depend on: the first pen's
// JumpSpeed, its source's laser words (below), MarkSpeed, LaserOnDelay, LaserOffDelay,
// PolygonDelay and JumpDelay — all of them, whatever an earlier list set. The board keeps its
// registers across lists and nothing documents their power-on values: a board left by EzCad, by
// another pen or by an aborted job (whose last packet never went out) holds values of its own, so
// the host never assumes one (as galvoplotter and meerk40t forget theirs on every new list).
// Within a list a word is sent again only when it changes.
//
// What each DeviceCommand becomes (docs/lmc.md has the full table):
// - pen i:   the pen's parameters whose words differ from what the list has set.
// - mark:    MarkSpeed when the speed word changes, MarkTo.
// - jump at speed 0 (travel): after a mark run the pen's mark delay as DelayTime (the board has
//            no mark-delay register: meerk40t's "end delay"), JumpSpeed / JumpDelay back to the
//            pen's when they differ, JumpTo. The board adds its jump delay after it.
// - jump at speed v ≠ 0 (a blanking run-in, run-out or join): a JumpTo at JumpSpeed v with the
//            board's JumpDelay set to 0. The LMC list has no "laser-off line at marking speed"
//            command, and a MarkTo with the power or port turned down is not laser-off on every
//            source (a fiber's simmer, a CO2 tickle) and would fire polygon delays. A JumpTo is
//            a straight constant-speed move with the laser gated off — exactly what a blanking
//            line is — as long as no jump delay stops the mirrors halfway through the run-in.
//            The laser-off delay still runs into it, which is what makes a run-out work.
// - timed move (duration_s > 0, look-ahead and feed-forward): lit, the pen's power word scaled
//            by its power fraction when that changes the word (MarkCurrent; MarkPowerRatio for
//            co2, uv), MarkSpeed; dark, JumpSpeed
//            with JumpDelay 0 (dark), the word that makes the move take its duration in ticks,
//            then MarkTo / JumpTo; one whose end rounds to where the mirrors are becomes a hold
//            of that many ticks (LaserOnPoint / DelayTime).
// - dwell:   laser off: DelayTime (10 µs units, split at 0xFFFF); laser on: LaserOnPoint (split
//            at 60000, the documented limit).
// - arc:     refused (describe() says arcs = false: the job chords arcs first).
// Moves to the point the mirrors are already at are dropped, as the reference drivers do.
//
// The laser words of each source (meerk40t balormk/controller.py, set_settings / power /
// frequency / fpk; galvoplotter galvo/controller.py, set):
// - fiber:   QSwitchPeriod (period in 50 ns = 20000 / f_kHz), MarkCurrent (12-bit power);
// - mopa:    the same, after FiberYLPMPulseWidth (ns) when the pen sets a pulse width;
// - co2, uv: MarkFreq (period in 100 ns = 10000 / f_kHz), SetCo2FPK (2000 / f_kHz, both words),
//            MarkPowerRatio (the PWM's high time in 50 ns = 200 · P% / f_kHz).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "driver/device.hpp"
#include "driver/lmc/codec.hpp"

namespace mark::lmc {

// A pen in board words, checked once at begin_job so a bad value is refused before anything
// is sent.
struct BoardPen {
  LaserSource source = LaserSource::fiber;
  std::uint16_t jump_speed = 0;
  std::uint16_t mark_speed = 0;
  std::array<std::uint16_t, 2> laser_on_delay{}, laser_off_delay{}, polygon_delay{}, jump_delay{};
  std::uint16_t qswitch_period = 0, power = 0;  // fiber, mopa
  std::optional<std::uint16_t> pulse_width;     // mopa, when the pen sets one
  std::uint16_t mark_period = 0, fpk = 0, power_ratio = 0;  // co2, uv
  std::uint16_t mark_delay_10us = 0;  // DelayTime after a mark run
};

// Throws InputError (settings the pen's source cannot take) or EncodeError (a value its word
// cannot carry), naming the pen ("pen 2: mark speed ...").
BoardPen encode_pen(const DevicePen& pen, std::size_t index, const FieldUnits& units);

// Where a full packet goes, with what it completes: the number of DeviceCommands of the job all
// of whose list commands are in this or an earlier packet, and the host's estimate of how long
// the board takes to execute it.
struct PacketInfo {
  std::uint64_t commands_complete = 0;
  double estimated_s = 0;
  bool last = false;  // the packet holding the job's EndOfList
  // The longest the board could take under every reading the references leave open: its
  // polygon delays read in 10 µs units whatever the host sent (a µs word read so is ten times
  // longer). What the session's deadline follows; ≥ estimated_s.
  double allowance_s = 0;
};
using PacketSink = std::function<void(const ListPacket&, const PacketInfo&)>;

// Counted as packets leave (a packet the sink refused, or one dropped by start_list, is not).
struct EncoderFigures {
  std::uint64_t list_commands = 0;  // list command words handed on (padding not counted)
  std::uint64_t packets = 0;
  std::uint64_t moves = 0;          // JumpTo + MarkTo
  std::uint64_t parameter_commands = 0;  // speeds, delays, laser settings
  double estimated_s = 0;           // the host's estimate of the board's execution time
};

class JobEncoder {
 public:
  JobEncoder(const FieldUnits& units, PacketSink sink);

  // A new list (after ResetList): anything left of an earlier list is dropped, then ReadyMark,
  // the open-MO delay as DelayTime (0: none), the output port as WritePort(list). Every
  // parameter is forgotten: the first pen applied sends all of them (the preamble).
  void start_list(double open_mo_delay_s, std::uint16_t port_bits);
  void apply_pen(const BoardPen& pen);
  // Appends one device command (already checked against the field by the caller). `index` is
  // its index in the job, for PacketInfo::commands_complete. A pen command puts nothing on the
  // wire: the caller resolves its index and calls apply_pen.
  void add(const DeviceCommand& c, std::uint64_t index);
  // Appends device commands first_index, first_index + 1, …: the same words as add() one by
  // one, with pen commands resolved in `pens` (EncodeError for an index beyond it).
  void add(std::span<const DeviceCommand> cs, std::uint64_t first_index,
           std::span<const BoardPen> pens);
  // The pen's mark delay if a mark run is open, EndOfList, and the last packet (padded).
  void finish(std::uint64_t commands_in_job);

  const EncoderFigures& figures() const { return figures_; }
  std::array<std::uint16_t, 2> position() const { return at_; }
  // The mirrors' position as the encoder last left it (new device: the field centre).
  void set_position(std::array<std::uint16_t, 2> at) { at_ = at; }
  bool in_mark_run() const { return in_run_; }
  // The board spends a tick on every word that is not a move (`marker lmc probe`: "a parameter
  // word takes a tick"; the emulated board's word_ticks): the estimate counts those ticks, and
  // timed moves give them back — each move after the first is shortened by the ticks the words
  // since the move before it took, down to one tick of its own, the rest owed by the moves
  // after — so the board's clock stays the host's and feed-forward's timing holds.
  void set_word_ticks(bool on) { word_ticks_ = on; }

 private:
  void push(const Word& c, double estimated_s = 0, double unverified_s = 0) {
    if (packet_.full()) flush_full();
    packet_.push(c);
    if (word_ticks_) [[unlikely]] {
      const Op op = static_cast<Op>(c.opcode());
      if (op != Op::JumpTo && op != Op::MarkTo && op != Op::EndOfList) {
        estimated_s += kTick_s;
        if (timed_) tick_debt_ += 1;
      }
    }
    packet_estimate_s_ += estimated_s;
    packet_unverified_s_ += unverified_s;
  }
  // Hands the packet to the sink and counts it once the sink took it.
  void emit_packet(const PacketInfo& info);
  void flush_full();
  void set_jump_speed(std::uint16_t w) {
    if (jump_speed_ != w) send_jump_speed(w);
  }
  void set_jump_delay(std::array<std::uint16_t, 2> d) {
    if (jump_delay_ != d) send_jump_delay(d);
  }
  void send_jump_speed(std::uint16_t w);
  void send_mark_speed(std::uint16_t w);
  void send_jump_delay(std::array<std::uint16_t, 2> d);
  void end_run();
  // Encodes the leading marks and jumps of `cs` (up to the first pen, dwell or arc, or a move
  // at the pen's speed with no pen applied); returns how many.
  std::size_t add_moves(std::span<const DeviceCommand> cs, std::uint64_t first_index);
  void add_timed(const DeviceCommand& c);
  // The move word to `to` at speed word `v`, with its share of the estimate (`corner`: after a
  // MarkTo of the same run, the board's polygon delay).
  void push_move(Op op, std::array<std::uint16_t, 2> to, std::uint16_t v, bool corner);
  // `ticks` with the mirrors still, the laser on (LaserOnPoint) or off (DelayTime).
  void hold(double ticks, bool laser);
  // The pen's power word scaled by `fraction` (0..1), sent if the board has another.
  void set_power(double fraction);

  FieldUnits units_;
  PacketSink sink_;
  ListPacket packet_;
  double packet_estimate_s_ = 0;
  double packet_unverified_s_ = 0;  // what an unverified reading could add (PacketInfo::allowance_s)
  std::uint64_t current_ = 0;  // index of the command being encoded
  EncoderFigures figures_;
  const BoardPen* pen_ = nullptr;
  std::array<std::uint16_t, 2> at_{0x8000, 0x8000};
  bool in_run_ = false;
  bool word_ticks_ = false;  // set_word_ticks
  bool timed_ = false;       // a timed move went out in this list: words after it are owed
  double tick_debt_ = 0;     // ticks the board spent on words that no move has given back yet
  // What the board has now (nullopt: unknown, send it).
  // The speed words the board has; kUnknown after a new list (sent again).
  static constexpr std::uint32_t kUnknown = 0x10000;
  std::uint32_t jump_speed_ = kUnknown, mark_speed_ = kUnknown;
  std::optional<std::uint16_t> qswitch_, power_, pulse_width_, mark_period_, fpk_, power_ratio_;
  std::optional<std::array<std::uint16_t, 2>> on_delay_, off_delay_, polygon_, jump_delay_;
  double jump_delay_s_ = 0;            // the jump delay's share of the estimate
  double polygon_s_ = 0;               // the polygon delay, for the estimate of corners
  double polygon_worst_s_ = 0;         // the same word read in 10 µs units
  std::array<std::int32_t, 2> last_d_{};  // the last move, for a corner's angle
  double last_length_ = 0;
  std::uint32_t inverse_for_ = 0;      // speed word the cached reciprocal belongs to
  double inverse_speed_ = 0;
};

}  // namespace mark::lmc
