#pragma once
// The BJJCZ LMC board as a command-level Device (driver/device.hpp): the job's DeviceCommands
// become list commands (job_encoder.hpp) streamed to the board with READY flow control
// (session.hpp); the pens' speeds, delays and laser settings are set on the board. The link
// underneath is USB (usb_link.hpp), a capture file (capture_link.hpp) or an emulated board.
//
// Safety:
// - every command of a submit() is checked against the lens field before any of it is encoded;
//   an outside point fails the job (out_of_field, naming the point) and nothing of it is sent;
// - any transfer error, link timeout, unplug, or a board that stops becoming READY / stops
//   being BUSY within the host's estimate fails the job: the stop sequence runs (laser port off
//   first, then StopExecute, master oscillator closed, list reset) wherever the board can still
//   be reached, and the fault says which commands were sent (and so may have been marked) and
//   from which command on nothing was sent. Nothing is retried: a stroke is never marked twice.
// - abort() from any thread and any state runs the same stop sequence; the board's laser port
//   stays off until the next job.
//
// Lifecycle (driver/device.hpp, driver/lifecycle.hpp): the one state machine of every device.
// Besides jobs, frame() runs idle → running → idle (it marks nothing); pause(), resume() need a
// running job, set_red_pointer() none. A reset() that cannot reach the board again leaves the
// device failed with a transport fault (a later reset() tries again).
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "driver/device.hpp"
#include "driver/lifecycle.hpp"
#include "driver/lmc/codec.hpp"
#include "driver/lmc/cor_file.hpp"
#include "driver/lmc/job_encoder.hpp"
#include "driver/lmc/link.hpp"
#include "driver/lmc/session.hpp"

namespace mark::lmc {

struct LmcOptions {
  double field_mm = 110;               // lens field (square), sets the units: 65535 / field
  double chord_tolerance_mm = 0.005;   // what describe() asks the job to chord arcs to
  AxisMap axes = kEzCadAxes;           // how the head is wired (EzCad's default)
  // µs with the sign flag, as galvoplotter and balor send it (meerk40t since 2025: 10 µs);
  // `marker lmc probe` measures which one a board takes.
  PolygonDelayUnit polygon_delay_unit = PolygonDelayUnit::signed_us;
  // The board spends a tick on every word that is not a move (`marker lmc probe` measures it):
  // the host then counts those ticks and timed moves give them back (JobEncoder::set_word_ticks).
  bool word_ticks = false;
  int laser_port_bit = 0;              // output port bit that enables the laser
  int red_pointer_bit = 8;             // output port bit of the red pointer
  double open_mo_delay_s = 0.008;      // DelayTime after opening the master oscillator
  double max_speed_mm_s = 20000;       // describe(): the fastest move we let a job ask for
  std::optional<CorrectionTable> correction;  // uploaded at init; none: WriteCorTable(0)
  InitParams init;
  SessionOptions session;
};

// Red-pointer framing: the paths are traced with the laser port off and the red pointer on.
struct FrameOptions {
  double speed_mm_s = 3000;  // red-light speed (meerk40t's default)
  std::uint64_t laps = 0;    // 0: until abort()
};

struct FrameReport {
  std::uint64_t laps = 0;      // laps handed to the board
  std::uint64_t packets = 0;
  bool stopped = false;        // ended by abort()
};

class LmcDevice : public CommandDevice {
 public:
  // Takes the link and runs the init sequence. Throws DeviceFaultError if the board does not
  // answer, DeviceError for options that make no sense.
  LmcDevice(std::unique_ptr<LmcLink> link, LmcOptions options);
  ~LmcDevice() override;

  DeviceDescription describe() const override;
  void begin_job(const JobHeader& header) override;
  void submit(std::span<const DeviceCommand> commands) override;
  DeviceReport end_job() override;
  void abort() noexcept override;
  DeviceStatus status() const override;
  void reset() override;

  // LMC specifics.
  const BoardIdentity& identity() const { return identity_; }
  // What the last stop sequence (abort, or a fault) achieved, command by command.
  StopOutcome last_stop() const;
  const LmcOptions& options() const { return options_; }
  void pause();   // StopList: the board holds with the laser off
  void resume();  // RestartList
  Vec2 query_position();                     // GetPositionXY, mm
  std::uint16_t query_status();              // the board's status register (lmc::status bits)
  void set_red_pointer(bool on);             // single WritePort (idle only)
  // Traces the polylines (mm) with the red pointer until `laps` are done or abort() is called;
  // then the red pointer is switched off. Idle only. Points outside the field are refused.
  FrameReport frame(const std::vector<std::vector<Vec2>>& paths, const FrameOptions& options);

  // Board I/O (docs/lmc.md "Board I/O"). The input port: ReadPort (0x0025), its reply's w1, as
  // meerk40t's read_port()[1]. Any thread, any state: the session interleaves it between a job's
  // transactions (the wire lock). Throws Aborted while an abort is pending, LinkError when the
  // board does not answer.
  std::uint16_t read_inputs();
  // The output bits a station drives (ready / busy / done / error): OR'ed into every port word
  // this device writes from now on — the job's WritePorts, the stop sequence's port-off, the
  // red pointer's. The laser and red-pointer bits (reserved_port_bits()) are masked off: a
  // signal never switches the laser. No I/O, never blocks (callable under another lock).
  void set_signal_bits(std::uint16_t bits) noexcept;
  std::uint16_t signal_bits() const noexcept { return signals_.load(std::memory_order_acquire); }
  std::uint16_t reserved_port_bits() const;
  // Puts the port word on the board now (laser off, the red pointer as last set, the signal
  // bits) when no job or frame runs, and returns true; while one runs it returns false and
  // writes nothing (its own port words carry the bits). Throws as read_inputs().
  bool write_outputs();

 private:
  struct Fault;
  void check_commands(std::span<const DeviceCommand> commands) const;
  void send_packet(const ListPacket& packet, const PacketInfo& info);
  [[noreturn]] void fail(FaultCategory category, const std::string& what);
  [[noreturn]] void fail_from(const std::exception& e);
  std::string stop_board() noexcept;  // the stop sequence; says what it achieved
  void collect_figures();
  std::uint16_t port_bits(bool laser, bool red) const;
  DeviceReport report() const;

  LmcOptions options_;
  FieldUnits units_;
  std::unique_ptr<LmcLink> link_;
  Lifecycle lifecycle_{"lmc"};            // before session_: it watches the abort request
  Session session_;
  BoardIdentity identity_;
  JobEncoder encoder_;

  std::mutex job_;                        // submit / end_job / begin_job / frame / reset
  mutable std::mutex report_mutex_;       // figures_ and position_ (status() reads them)
  DeviceFigures figures_;                 // of the last job, for report()

  // The job.
  JobHeader header_;
  std::vector<BoardPen> pens_;
  LaserSource source_ = LaserSource::fiber;  // the job's (every pen's) source
  std::uint64_t commands_ = 0;            // DeviceCommands submitted
  std::atomic<std::uint64_t> commands_sent_{0};  // all of whose list commands reached the board
  std::uint64_t packets_ = 0;
  std::uint64_t list_commands_at_start_ = 0, parameters_at_start_ = 0, moves_at_start_ = 0;
  double estimate_at_start_s_ = 0;
  SessionFigures session_at_start_;
  std::chrono::steady_clock::time_point job_start_{};
  std::chrono::steady_clock::time_point last_good_{};   // last transfer that succeeded
  double fault_latency_s_ = -1;           // last good transfer → fault reported
  double first_packet_s_ = -1;            // begin_job → first list packet on the wire
  double device_time_s_ = 0;
  std::atomic<bool> laser_on_{false};     // the board's laser port as last set
  std::atomic<bool> red_on_{false};       // the red pointer as set_red_pointer() left it
  std::atomic<std::uint16_t> signals_{0}; // set_signal_bits(): in every port word
  std::optional<StopOutcome> last_stop_;  // guarded by report_mutex_
  Vec2 position_{0, 0};
};

}  // namespace mark::lmc
