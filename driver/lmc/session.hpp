#pragma once
// The conversation with one LMC board over a link (galvo.md §1.7–§1.8): the init sequence,
// single commands and their replies, list streaming with READY flow control, job end, pause /
// resume, the stop sequence, status and position queries. The wire format itself is codec.hpp.
//
// Flow control, as galvoplotter and meerk40t do it on real boards: before each list packet,
// poll the status (GetVersion's status word) until READY; write the packet; send
// SetEndOfList(0); after the third packet send ExecuteList once (a shorter job sends it after
// its last packet). At the end, poll until BUSY clears. Nothing waits for ever: a wait that
// outlasts the host's own estimate of the work queued on the board plus a grace period is a
// timeout fault.
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
  double settle_s = 0.05;   // the reference drivers' closing sleep (papers over a board race)
};

struct SessionOptions {
  double poll_interval_s = 0.002;   // between status polls while waiting
  double grace_s = 1.0;             // how far READY / not-BUSY may lag the host's estimate
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
  std::optional<std::chrono::steady_clock::time_point> first_packet_at, execute_at;
  std::chrono::steady_clock::time_point last_ok{};  // the last transfer that succeeded
};

// What the stop sequence achieved.
struct StopOutcome {
  bool laser_off_confirmed = false;  // the board acknowledged WritePort with the laser bit clear
  bool reached = false;              // any command of the sequence got an answer
  std::string note;                  // why it stopped early, if it did
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
  void send_packet(const ListPacket& packet, double estimated_s);
  void finish_list();
  void wait_idle();
  bool executing() const { return executed_; }
  std::size_t packets_in_list() const { return packets_in_list_; }

  void pause();   // StopList
  void resume();  // RestartList

  // The stop sequence, for abort and faults, in this order: WritePort(port_off) so the laser
  // stops at once, StopExecute, Fiber_SetMo(0), ResetList, a flush list (EndOfList +
  // ExecuteList, as meerk40t; only if the board is READY), WritePort(port_off) again in case the
  // list set it in between. A stall is cleared and the step retried once; a timeout or an
  // unplugged board ends the sequence (nothing more can be reached). Never throws.
  StopOutcome stop(std::uint16_t port_off, bool fiber) noexcept;

  SessionFigures figures();  // a copy, taken under the wire lock
  LmcLink& link() { return link_; }

 private:
  Reply transact(const Word& c, bool stopping);
  void write_packet(const ListPacket& packet, bool stopping);
  void check_abort(bool stopping) const;
  std::uint16_t poll_locked();
  template <class Done>
  double poll_until(Done done, const std::string& waiting_for);
  void sleep_poll() const;

  LmcLink& link_;
  SessionOptions options_;
  const std::atomic<bool>& abort_;
  std::recursive_mutex wire_;
  SessionFigures figures_;
  std::size_t packets_in_list_ = 0;
  bool executed_ = false;
  double queued_s_ = 0;  // estimated work sent in this list
  std::chrono::steady_clock::time_point execute_start_{};
  std::atomic<bool> paused_{false};
  double paused_s_ = 0;  // time spent paused since ExecuteList (not counted against deadlines)
};

}  // namespace mark::lmc
