#pragma once
// Test support: an LMC board in software, byte for byte. It takes the host's bulk transfers
// (12-byte commands and 3072-byte list packets on EP 0x02), decodes every word against the
// codec's table, answers single commands with 8-byte replies (EP 0x88) carrying its status
// register, keeps a list buffer of a few packets with READY / BUSY behaviour, and executes the
// list on its own 10 µs clock (list_executor.hpp) into the simulated scanner. The umockdev
// fixture (tests/driver/lmc/usb/) puts it behind real usbfs ioctls; LoopbackLink puts it behind
// the driver directly.
//
// It also checks the host: a packet arriving while READY is clear (and so lost), a transfer of
// the wrong size, a single opcode in a packet or a list opcode alone, an unknown opcode, words
// other than padding after EndOfList, a move whose distance word disagrees with its geometry —
// each is recorded in violations().
//
// Faults to inject: withhold READY for a while after the n-th packet, stall EP 0x02 at the n-th
// packet (until the host clears the halt), stop answering from the n-th packet (transfers time
// out) for a while or for good, unplug at the n-th packet or some device time after
// ExecuteList. Unplugging only cuts USB: like the real, separately powered board, it goes on
// executing what it has buffered (and then waits with the laser gate closed).
//
// Thread-safe: the USB side, the clock thread and the test's inspection all take one lock.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "driver/lmc/codec.hpp"
#include "driver/lmc/list_executor.hpp"
#include "ringbuffer/scan_sample.hpp"
#include "ringbuffer/sink.hpp"

namespace mark::lmc {

struct BoardOptions {
  double field_mm = 110;  // for decoding coordinates only (the board itself works in units)
  AxisMap axes = kEzCadAxes;
  // How the board reads PolygonDelay: µs with the sign flag unless a variant says otherwise
  // (the host's default too; docs/lmc.md).
  PolygonDelayUnit polygon_delay_unit = PolygonDelayUnit::signed_us;
  std::size_t list_capacity = 4;  // packets the board buffers (READY clears when full)
  // What the open drivers leave open (list_executor.hpp), and the laser on its outputs.
  ExecutorBehaviour behaviour;
  std::uint32_t serial = 0x4C4D4301;
  std::array<std::uint16_t, 3> version{0x0001, 0x0010, 0x0002};
  int laser_bit = 0, red_bit = 8;
  std::uint16_t input_port = 0;  // the input word ReadPort answers until set_inputs()
  Sink<ScanSample>* scanner = nullptr;  // where the executed list goes (may be null)
};

// The board's behaviour variants: every reading of the board the open drivers leave open, by
// name, so a test of the session (and `marker lmc probe` in CI) runs against each.
struct BoardVariant {
  std::string_view name;  // a C identifier, for test names and --board-variant
  std::string_view what;
  void (*apply)(BoardOptions&);
};
// A variant prints as its name (logs, and test parameters in CTest's list).
inline std::ostream& operator<<(std::ostream& os, const BoardVariant& v) { return os << v.name; }
std::span<const BoardVariant> board_variants();
// The options with the variant applied; DeviceError naming the known ones for an unknown name.
BoardOptions with_variant(BoardOptions options, std::string_view name);

// One single command answered wrongly, to test what the host does about it (the stop
// sequence): the `occurrence`-th time (1-based) the board receives `opcode`, it stalls EP 0x02
// (until CLEAR_HALT), takes the command but never answers (the host's read times out), takes
// nothing for `hang_s` (the write times out), or is unplugged.
struct SingleFault {
  enum class Kind { stall, no_answer, hang, unplug };
  std::uint16_t opcode = 0;
  std::size_t occurrence = 1;
  Kind kind = Kind::no_answer;
  double hang_s = 0.05;  // device time: shorter than the link timeout, so the next write gets through
};

struct BoardFaults {
  std::optional<std::size_t> withhold_ready_after_packet;  // 1-based packet number
  double withhold_ready_s = 0.2;                           // device time
  std::optional<std::size_t> stall_at_packet;
  std::optional<std::size_t> hang_at_packet;
  double hang_s = 0;                                       // 0: for good
  std::optional<std::size_t> unplug_at_packet;
  std::optional<double> unplug_after_execute_s;            // device time after ExecuteList
  std::optional<SingleFault> single;
};

// What happens to one URB.
enum class Urb { done, stall, no_device, pending };

struct WireRecord {
  double t_s = 0;               // device time of arrival
  bool packet = false;
  Word single;                  // when !packet
  std::size_t packet_number = 0;  // 1-based, when packet
  std::uint16_t status = 0;     // the status register when it arrived
  // The host's steady clock when it arrived: a station's trigger to the board's first sample
  // (ExecuteList) is measured against it (bench/prog_station_board_io.cpp).
  std::chrono::steady_clock::time_point arrived{};
};

struct BoardState {
  std::uint16_t port = 0;
  bool laser_emitting = false;
  bool executing = false, paused = false, finished = false;
  bool mo_open = false, laser_enabled = false;
  bool unplugged = false;
  std::size_t buffered_packets = 0;
  std::uint16_t status = 0;
  double device_time_s = 0;
  std::array<std::uint16_t, 2> position{};
  ExecutorFigures executor;
  std::size_t packets_received = 0, packets_lost = 0;
  std::size_t cor_lines = 0;
  std::optional<std::uint16_t> cor_table;  // the last WriteCorTable argument
  std::size_t read_ports = 0;  // ReadPort commands answered
};

class EmulatedBoard : private ListFeed {
 public:
  explicit EmulatedBoard(BoardOptions options = {}, BoardFaults faults = {});
  ~EmulatedBoard() override;
  EmulatedBoard(const EmulatedBoard&) = delete;
  EmulatedBoard& operator=(const EmulatedBoard&) = delete;

  // USB side.
  Urb out(std::span<const std::uint8_t> bytes);                // EP 0x02
  Urb in(std::array<std::uint8_t, kReplyBytes>& reply);        // EP 0x88
  void clear_halt();

  // The board's clock: a thread advancing it `time_scale` × as fast as the wall clock, or
  // manual steps.
  void start_clock(double time_scale = 1.0);
  // A virtual clock: the list runs as fast as the thread can execute it, but never past the
  // data it has (no underrun of its own making); while it waits, time passes as the wall clock's.
  void start_virtual_clock();
  void stop_clock();
  void advance(double seconds);

  // The laser on the board's outputs from now on (the job's source).
  void set_source(LaserSource source);

  // Arms a single-command fault from now on (occurrences counted from here).
  void set_single_fault(const SingleFault& fault);

  // Unplug now; `on_unplug` (set before) is called once, outside the lock (the umockdev
  // fixture sends the "remove" uevent from it).
  void unplug();
  std::function<void()> on_unplug;

  // The input pins (ReadPort's w1) from now on: what a foot switch or a PLC output would do.
  void set_inputs(std::uint16_t bits);
  std::uint16_t inputs() const;

  // Inspection.
  BoardState state() const;
  // Every output port word the board took, in order (single WritePort and list WritePort).
  std::vector<PortWrite> port_writes() const;
  bool unplugged() const;
  std::vector<WireRecord> wire() const;  // every transfer but ReadPort (BoardState::read_ports)
  std::vector<std::vector<Word>> packets() const;  // every packet received, in order
  std::vector<std::string> violations() const;
  std::vector<Vec2> red_path() const;
  // Blocks until the list finished executing (or `timeout_s` of wall time passed).
  bool wait_finished(double timeout_s) const;
  // Runs `f` under the board's lock (e.g. to read the scanner while the clock runs).
  void inspect(const std::function<void()>& f) const;
  const FieldUnits& units() const { return units_; }

 private:
  const Word* peek() override;
  void pop() override;
  std::uint16_t status_locked() const;
  bool ready_locked() const;
  void on_single(const Word& w);
  std::optional<Urb> single_fault(const Word& w);
  void check_source_word(std::uint16_t op, const std::string& where);
  void on_packet(std::span<const std::uint8_t> bytes);
  void violation(std::string what);
  void advance_locked(std::uint64_t ticks);
  void unplug_locked();

  BoardOptions options_;
  BoardFaults faults_;
  FieldUnits units_;
  mutable std::mutex mutex_;
  mutable std::condition_variable finished_cv_;
  ListExecutor executor_;
  std::deque<std::vector<Word>> buffer_;  // packets not yet fully executed
  std::size_t cursor_ = 0;                // next word of buffer_.front()
  std::deque<std::array<std::uint8_t, kReplyBytes>> replies_;
  std::vector<WireRecord> wire_;
  std::vector<std::vector<Word>> packets_;
  std::vector<std::string> violations_;
  std::uint64_t ticks_ = 0;
  std::size_t packets_seen_ = 0;  // packet transfers the host attempted
  std::size_t packets_lost_ = 0;
  double withhold_until_s_ = -1;
  bool stalled_ = false, unplugged_ = false;
  std::size_t single_fault_seen_ = 0;  // occurrences of faults_.single->opcode
  bool drop_next_reply_ = false;
  double hang_until_s_ = -1;      // < 0: not hanging; +inf: for good
  std::optional<double> execute_at_s_;
  bool cor_open_ = false;
  std::size_t cor_lines_ = 0;
  std::optional<std::uint16_t> cor_table_;
  bool laser_enabled_ = false;
  std::uint16_t inputs_ = 0;
  std::size_t read_ports_ = 0;

  std::thread clock_;
  std::atomic<bool> clock_run_{false};
};

}  // namespace mark::lmc
