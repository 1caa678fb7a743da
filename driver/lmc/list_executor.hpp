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
//
// Where the open drivers leave the board's behaviour open, ExecutorBehaviour picks one reading
// (docs/lmc.md, "Not verified on a real board"; `marker lmc probe` measures each on a board):
// exact instead of whole-tick move times, a tick for every parameter word, a JumpTo that waits
// out the laser-off delay, the polygon delay's unit, and the registers a board starts with.
// The laser words a source takes set the light's power: MarkCurrent (fiber, MOPA), or
// MarkPowerRatio over MarkFreq (CO2, UV: the PWM duty).
#include <array>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "driver/laser_source.hpp"
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

// How the executor reads what the open drivers leave open (see the top).
struct ExecutorBehaviour {
  // Moves take their exact time, the fraction of a tick carried to the next move, instead of
  // ⌈length / step⌉ whole ticks each.
  bool exact_move_time = false;
  // Every word that is not a move (speeds, delays, laser words, WritePort, DelayTime,
  // LaserOnPoint) takes one tick of its own.
  bool word_ticks = false;
  // A JumpTo after a mark run waits (mirrors still) until the laser-off delay has run out.
  bool jump_waits_off_delay = false;
  // The registers start as a board another program left (not 0): jump delay 500 µs, laser
  // delays 200 / 250 µs, polygon delay 500 (in the board's unit), mark and jump speed words 300
  // and 2000, half power, 20 kHz.
  bool foreign_settings = false;
  LaserSource source = LaserSource::fiber;  // the laser on the outputs: its words set the power
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
  // The output from the list's first lit tick on (position, gate, power of every tick), hashed
  // (FNV-1a): two runs that mark alike give the same hash whatever led up to the first mark.
  std::uint64_t lit_stream_hash = 0;
  double power_fraction = 0;   // the light's power as the source's words last set it, 0..1
  double frequency_khz = 0;    // the pulse (or PWM) frequency they last set
  double pulse_width_ns = 0;   // FiberYLPMPulseWidth, if sent
};

// One output port word the board took (the tests read what a station's signals did to it).
struct PortWrite {
  std::uint16_t bits = 0;
  bool list = false;  // list WritePort (0x8011), else the single WritePort (0x0021)
  bool operator==(const PortWrite&) const = default;
};

class ListExecutor {
 public:
  ListExecutor(const FieldUnits& units, int laser_bit, int red_bit, ExecutorBehaviour behaviour = {});

  void set_scanner(Sink<ScanSample>* scanner) { scanner_ = scanner; }
  void start();   // ExecuteList
  void stop();    // StopExecute / ResetList: the current move is dropped, the gate closes
  void set_paused(bool paused) { paused_ = paused; }
  // Runs `ticks` ticks (none while not executing or paused). With `stop_at_underrun` (the
  // virtual clock) it returns at the first tick that would wait for data instead, and says how
  // many ticks it ran.
  std::uint64_t run(std::uint64_t ticks, ListFeed& feed, bool stop_at_underrun = false);

  bool executing() const { return executing_; }
  const ExecutorBehaviour& behaviour() const { return behaviour_; }
  void set_source(LaserSource source) {
    behaviour_.source = source;
    update_power();
  }
  bool paused() const { return paused_; }
  bool finished() const { return finished_; }

  // Single-command state.
  void write_port(std::uint16_t bits) { set_port(bits, false); }
  std::uint16_t port() const { return port_; }
  // Every port word taken, single and list WritePort alike, in order (the tests' port record).
  const std::vector<PortWrite>& port_writes() const { return port_writes_; }
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
  void hold_ticks(std::uint64_t n, bool forced_gate);
  void tick(std::vector<ScanSample>& out);
  void emit(bool gate, std::vector<ScanSample>& out);
  ScanSample sample(bool light) const;
  void set_laser_word(const Word& w);  // a source's laser word: power, frequency
  void update_power();
  void set_port(std::uint16_t bits, bool list);

  FieldUnits units_;
  int laser_bit_, red_bit_;
  ExecutorBehaviour behaviour_;
  double move_carry_ = 0;            // exact_move_time: the fraction of a tick carried
  Sink<ScanSample>* scanner_ = nullptr;
  bool executing_ = false, paused_ = false, finished_ = false, ending_ = false;
  std::uint16_t port_ = 0;
  bool enabled_ = false, mo_ = false, emitting_ = false;
  std::array<double, 2> pos_{32768, 32768};      // where the list leaves the mirrors
  std::array<double, 2> pos_out_{32768, 32768};  // where they are commanded this tick
  std::deque<Activity> acts_;
  // List parameters (the board's registers: kept from list to list).
  std::uint16_t jump_speed_ = 0, mark_speed_ = 0, power_ = 0xFFF;
  std::uint16_t mark_period_ = 0, power_ratio_ = 0;  // CO2 / UV
  double on_delay_s_ = 0, off_delay_s_ = 0, jump_delay_s_ = 0, polygon_s_ = 0;
  double light_power_ = 1;  // 0..1, from the source's words
  bool lit_seen_ = false;   // the list has emitted a lit tick (lit_stream_hash runs from it)
  // Mark-run state.
  bool run_ = false;
  std::uint64_t on_countdown_ = 0, off_tail_ = 0;
  std::array<double, 2> run_dir_{};  // direction of the run's last move
  bool in_underrun_ = false;
  ExecutorFigures figures_;
  std::vector<Vec2> red_path_;
  std::vector<PortWrite> port_writes_;
};

}  // namespace mark::lmc
