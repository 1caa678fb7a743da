#pragma once
// Test support: how the emulated LMC board executes a list on its own 10 µs clock, one tick at
// a time, into ScanSamples for the simulated scanner (driver/sim/sim_scanner.hpp). This is our model
// of the board — RTC-class semantics (galvo.md §3.1), since BJJCZ documents none:
//
// - JumpTo / MarkTo: a straight move from the current point at the jump / mark speed word
//   (units per ms → speed/100 units per tick), n = ⌈length / step⌉ ticks, sample k at k/n of the
//   way (the last step lands on the target), rounded to whole units as the 16-bit DACs do.
// - A mark run is consecutive MarkTo (parameter commands in between do not break it; JumpTo,
//   DelayTime, LaserOnPoint and EndOfList do). The laser gate opens LaserOnDelay after the run
//   starts (the mirrors already moving; a negative delay holds the mirrors that long at the
//   start with the gate open) and closes LaserOffDelay after the run's last move ends, while
//   whatever follows executes (a jump, a delay): positive laser delays cost no time.
// - Between two MarkTo of a run the mirrors hold PolygonDelay × (1 − cos φ) with the gate open
//   (φ the turn angle: RTC's default variable polygon delay).
// - After every JumpTo the mirrors hold JumpDelay. DelayTime holds; LaserOnPoint holds with the
//   gate open.
// - Light leaves the board when the gate is open, output-port bit `laser_bit` is set,
//   EnableLaser was sent and the fiber's master oscillator is open; its power is MarkCurrent.
// - Waiting for list data that has not arrived (an underrun) holds the mirrors with the gate
//   closed and is counted; a negative LaserOffDelay is treated as 0 (counted).
#include <array>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "driver/lmc/codec.hpp"
#include "driver/vec2.hpp"
#include "ringbuffer/scan_sample.hpp"
#include "ringbuffer/sink.hpp"

namespace mark::lmc {

// Where the executor reads its list words: the board's packet buffer.
class ListFeed {
 public:
  virtual ~ListFeed() = default;
  virtual const Word* peek() = 0;  // the next word, or nullptr if none has arrived
  virtual void pop() = 0;
};

struct ExecutorFigures {
  std::uint64_t executed = 0;        // list words executed (padding after EndOfList not counted)
  std::uint64_t moves = 0;
  std::uint64_t ticks = 0;           // ticks spent executing
  std::uint64_t lit_ticks = 0;       // ticks with light leaving the board
  std::uint64_t underrun_events = 0;
  std::uint64_t underrun_ticks = 0;
  std::uint64_t unsupported = 0;     // words the model does not execute (WaitForInput, ...)
  std::uint64_t distance_mismatches = 0;  // a move's distance word ≠ its geometry (±1)
};

class ListExecutor {
 public:
  ListExecutor(const FieldUnits& units, int laser_bit, int red_bit);

  void set_scanner(Sink<ScanSample>* scanner) { scanner_ = scanner; }
  void start();   // ExecuteList
  void stop();    // StopExecute / ResetList: the current move is dropped, the gate closes
  void set_paused(bool paused) { paused_ = paused; }
  // Runs `ticks` ticks (none while not executing or paused).
  void run(std::uint64_t ticks, ListFeed& feed);

  bool executing() const { return executing_; }
  bool paused() const { return paused_; }
  bool finished() const { return finished_; }

  // Single-command state.
  void write_port(std::uint16_t bits) { port_ = bits; }
  std::uint16_t port() const { return port_; }
  void set_enabled(bool on) { enabled_ = on; }
  void set_mo(bool open) { mo_ = open; }
  bool mo_open() const { return mo_; }
  void goto_xy(std::array<std::uint16_t, 2> to) { pos_ = pos_out_ = {double(to[0]), double(to[1])}; }
  std::array<std::uint16_t, 2> position() const;
  bool emitting() const { return emitting_; }

  const ExecutorFigures& figures() const { return figures_; }
  // The red pointer's path: every move target while the red-pointer bit was set (mm).
  const std::vector<Vec2>& red_path() const { return red_path_; }

 private:
  struct Activity {
    bool move = false;
    std::array<double, 2> from{}, to{};
    std::uint64_t n = 0, k = 0;  // ticks of a move / hold, and done
    bool forced_gate = false;    // LaserOnPoint
  };
  bool fetch(ListFeed& feed);  // starts the next activity; false on an underrun
  void begin_move(const Word& w, bool mark);
  void end_run();
  void hold(double seconds, bool forced_gate);
  void tick(std::vector<ScanSample>& out);
  void emit(bool gate, std::vector<ScanSample>& out);
  ScanSample sample(bool light) const;

  FieldUnits units_;
  int laser_bit_, red_bit_;
  Sink<ScanSample>* scanner_ = nullptr;
  bool executing_ = false, paused_ = false, finished_ = false, ending_ = false;
  std::uint16_t port_ = 0;
  bool enabled_ = false, mo_ = false, emitting_ = false;
  std::array<double, 2> pos_{32768, 32768};      // where the list leaves the mirrors
  std::array<double, 2> pos_out_{32768, 32768};  // where they are commanded this tick
  std::deque<Activity> acts_;
  // List parameters.
  std::uint16_t jump_speed_ = 0, mark_speed_ = 0, power_ = 0xFFF;
  double on_delay_s_ = 0, off_delay_s_ = 0, jump_delay_s_ = 0, polygon_s_ = 0;
  // Mark-run state.
  bool run_ = false;
  std::uint64_t on_countdown_ = 0, off_tail_ = 0;
  std::array<double, 2> run_dir_{};  // direction of the run's last move
  bool in_underrun_ = false;
  ExecutorFigures figures_;
  std::vector<Vec2> red_path_;
};

}  // namespace mark::lmc
