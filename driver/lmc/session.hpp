#pragma once
// The conversation with one LMC board over a link (galvo.md §1.7–§1.8): the init sequence,
// single commands and their replies, list streaming with READY flow control, job end, pause /
// resume, the stop sequence, status and position queries. The wire format itself is codec.hpp.
//
// Flow control, as galvoplotter and meerk40t do it on real boards: before each list packet,
// poll the status (GetVersion's status word) until READY; write the packet; send
// SetEndOfList(0); after the third packet send ExecuteList once (a shorter job sends it after
// its last packet; a board whose buffer fills before the third — READY clear and nothing
// executing — gets it then, or it would wait for ever). At the end, poll until BUSY clears.
//
// How long a wait may last follows the board, not a clock of its own: a board that answers and
// is BUSY is working (galvoplotter and meerk40t poll without any deadline). What ends a wait is a
// board that stops answering (every poll is a transfer with the link's timeout), or one that is
// still BUSY (or not READY) far past what it was given: more than (1 + estimate_margin) × the
// host's estimate of every packet sent since ExecuteList, plus grace_s, of time since ExecuteList
// with the time paused not counted (the allowance: the estimate, with the polygon delays read in
// the longer of their two disputed units). The estimate is a lower bound (whole ticks per move, a jump
// that waits out the laser-off delay and the like make a real list take longer: docs/lmc.md);
// the margin is there so a slow board is never taken for a dead one.
//
// Threads: every transaction (a command and its reply, a packet and its SetEndOfList) holds
// the wire lock, so abort() on another thread interleaves between transactions, never inside
// one. Once abort is requested, only the stop sequence's own transactions get on the wire;
// everything else throws Aborted — so no packet or ExecuteList can follow a stop.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "driver/lmc/codec.hpp"
#include "driver/lmc/cor_file.hpp"
#include "driver/lmc/link.hpp"

namespace mark::lmc {

// The init parameters EzCad and the open-source drivers send (galvo.md §1.8); their meaning is
// mostly undocumented, so the defaults are theirs.
struct InitParams {
  std::uint16_t control_mode = 0;
  std::uint16_t laser_mode = 1;
  std::uint16_t delay_mode = 1;
  std::uint16_t timing = 1;
  std::array<std::uint16_t, 2> standby{2000, 20};
  std::uint16_t first_pulse_killer = 200;
  std::uint16_t pwm_half_period = 125;
  std::uint16_t pwm_pulse_width = 125;
  std::array<std::uint16_t, 4> fpk2{0xFFB, 1, 409, 100};
  std::array<std::uint16_t, 4> fly_res{0, 99, 1000, 25};
  std::uint16_t analog_port_1 = 0x7FF;
  bool fiber = true;        // Fiber_SetMo(0) during init
  bool enable_laser = true; // EnableLaser (the probe leaves it out: it never fires)
  double settle_s = 0.05;   // the reference drivers' closing sleep (papers over a board race)
};

struct SessionOptions {
  double poll_interval_s = 0.002;   // between status polls while waiting
  // A wait ends with BoardTimeout once the time since ExecuteList (not paused) exceeds
  // (1 + estimate_margin) × the estimate of what was sent + grace_s.
  double estimate_margin = 1.0;
  double grace_s = 1.0;
  std::size_t execute_after_packets = 3;
};

struct BoardIdentity {
  std::string serial;     // GetSerialNo w1 w2 as 8 hex digits
  std::array<std::uint16_t, 3> version{};  // GetVersion w0..w2
};

// Thrown by session waits and transactions once abort was requested.
class Aborted : public DeviceError {
 public:
  Aborted() : DeviceError("lmc: aborted") {}
};

// The board did not become READY / stop being BUSY in time. (Link timeouts are LinkError.)
class BoardTimeout : public DeviceError {
 public:
  using DeviceError::DeviceError;
};

struct SessionFigures {
  std::uint64_t single_commands = 0;
  std::uint64_t packets = 0;
  std::uint64_t status_polls = 0;
  std::uint64_t ready_waits = 0;       // packets that had to wait for READY
  double ready_wait_s = 0;             // total time spent waiting for READY
  double idle_wait_s = 0;              // total time spent waiting for BUSY to clear
  std::optional<std::chrono::steady_clock::time_point> first_packet_at, execute_at;
  std::chrono::steady_clock::time_point last_ok{};  // the last transfer that succeeded
};

// One command of the stop sequence and what became of it.
struct StopStep {
  enum class Result {
    acknowledged,   // written, and the board answered
    unanswered,     // written, but no answer came (the link's timeout)
    not_written,    // the transfer failed (timeout, stall that did not clear, i/o error)
    unreachable,    // not tried: the board was gone (unplugged) before it
    skipped         // not needed (the flush list, when the board was not READY)
  };
  std::string command;  // "WritePort(0)", "StopExecute", ...
  Result result = Result::unreachable;
  std::string why;      // the link's error, when not acknowledged
};
std::string_view to_string(StopStep::Result result);

// What the stop sequence achieved.
struct StopOutcome {
  std::vector<StopStep> steps;
  bool laser_off_confirmed = false;  // a WritePort with the laser bit clear was acknowledged
  bool reached = false;              // any command of the sequence got an answer
  // The board acknowledged StopExecute and Fiber_SetMo(0): the list is stopped and the master
  // oscillator closed. Only then is a stop reported as done.
  bool stopped = false;
  // "stopped (acknowledged: WritePort(0), StopExecute, …)" or "NOT confirmed stopped:
  // StopExecute unanswered (…); …" — every command that was not acknowledged, and why.
  std::string summary() const;
};

class Session {
 public:
  Session(LmcLink& link, SessionOptions options, const std::atomic<bool>& abort_requested);

  // GetSerialNo, GetVersion, Reset, WritePort(0), the correction table (or WriteCorTable(0)),
  // EnableLaser and the mode/timing parameters, then the settle sleep.
  BoardIdentity initialise(const InitParams& params, const CorrectionTable* table);
  void upload_correction(const CorrectionTable* table);

  // A single command and its reply (WriteCorLine: no reply is read).
  Reply command(const Word& c);
  std::uint16_t poll_status();  // GetVersion's status word
  std::array<std::uint16_t, 2> position();  // GetPositionXY, board words

  // Lists. begin_list after ResetList; send_packet blocks for READY; finish_list sends
  // ExecuteList if the list never started; wait_idle polls until not BUSY.
  void begin_list();
  // `allowance_s`: the longest the packet could take (PacketInfo::allowance_s), what the
  // deadline follows; below `estimated_s` (the default) it is the estimate.
  void send_packet(const ListPacket& packet, double estimated_s, double allowance_s = 0);
  void finish_list();
  void wait_idle();
  bool executing() const { return executed_; }
  // When the list was started (ExecuteList), if it was.
  std::optional<std::chrono::steady_clock::time_point> executed_at() const {
    return executed_ ? std::optional(execute_start_) : std::nullopt;
  }
  std::size_t packets_in_list() const { return packets_in_list_; }

  void pause();   // StopList
  void resume();  // RestartList
  // Seconds the list has run since ExecuteList, time paused not counted (0 before).
  double running_s() const;

  // The stop sequence, for abort and faults, in this order: WritePort(port_off) so the laser
  // stops at once, StopExecute, Fiber_SetMo(0), ResetList, a flush list (EndOfList +
  // ExecuteList, as meerk40t; only if a status poll says READY), WritePort(port_off) again in
  // case the list set it in between. Every command is written whatever became of the ones
  // before it — a timed-out answer does not mean the OUT endpoint is dead — except after the
  // board is gone (no device), and except after two writes in a row failed (the board takes
  // nothing: only the closing WritePort is still tried). A stall is cleared (CLEAR_HALT) and
  // that command written once more. Each failing command costs at most the link's timeout, so
  // a board that takes nothing costs three. Never throws.
  StopOutcome stop(std::uint16_t port_off) noexcept;

  SessionFigures figures();  // a copy, taken under the wire lock
  LmcLink& link() { return link_; }

 private:
  Reply transact(const Word& c, bool stopping);
  void write_packet(const ListPacket& packet, bool stopping);
  void check_abort(bool stopping) const;
  std::uint16_t poll_locked();
  template <class Done>
  double poll_until(Done done, const char* waiting_for);
  void sleep_poll() const;
  double paused_total_s() const;

  LmcLink& link_;
  SessionOptions options_;
  const std::atomic<bool>& abort_;
  std::recursive_mutex wire_;
  SessionFigures figures_;
  std::size_t packets_in_list_ = 0;
  bool executed_ = false;
  double queued_s_ = 0;  // estimated work sent in this list
  double allowed_s_ = 0;  // the longest it could take (allowance_s)
  std::chrono::steady_clock::time_point execute_start_{};
  // Pauses (StopList … RestartList, from any thread): not counted against the deadline.
  mutable std::mutex pause_mutex_;
  bool paused_ = false;
  std::chrono::steady_clock::time_point paused_at_{};
  double paused_s_ = 0;  // closed pauses since ExecuteList
};

}  // namespace mark::lmc
