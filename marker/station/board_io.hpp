#pragma once
// The station's hardware handshake on a marking board's own ports (issue 22, docs/station.md
// "Board I/O"), as EzCad's "mark on input": `--trigger lmc-input:BIT` starts one mark on a
// rising edge of an input pin (foot switch, light barrier, PLC output), `--signal
// ready=B,busy=B,done=B,error=B` drives output pins with station_lights(). It is one more adapter
// of the Station's calls (mark_async, the state events), like the TCP and Modbus servers: it
// knows no board — the port functions are given (marker/cli/serve_board_io.cpp wires an LMC
// board's ReadPort / WritePort to them).
//
// Polling: the input is read every `poll_idle_s` (1 ms) while the station is not marking and
// every `poll_marking_s` (10 ms) while it is: the LMC session interleaves a ReadPort between a
// job's transactions (its wire lock), and the slower rate keeps the polls from taking the link
// from the job's packets; an edge while marking only has to be seen to be logged and ignored.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>

#include "marker/station/station.hpp"

namespace mark {

// The board's side, as functions (any thread; only the poller's thread calls them).
struct BoardPort {
  // The input word (bit n = pin n). Throws when the board does not answer.
  std::function<std::uint16_t()> read_inputs;
  // The output bits from now on: no I/O, never blocks (it runs under the station's lock).
  std::function<void(std::uint16_t)> set_outputs;
  // Puts them on the board now; false when a job runs (its own port words carry them). Throws
  // when the board does not answer.
  std::function<bool()> write_outputs;
};

// Output bit of each signal (none: not driven).
struct BoardSignals {
  std::optional<int> ready, busy, done, error;
  std::uint16_t mask() const;                        // every bit used
  std::uint16_t word(const StationLights& l) const;  // the bits the lights set
};

struct BoardIoOptions {
  std::optional<int> trigger_bit;  // --trigger lmc-input:BIT
  BoardSignals signals;            // --signal
  double debounce_s = 0.005;       // --trigger-debounce-ms
  double min_pulse_s = 0.005;      // --trigger-min-pulse-ms
  double poll_idle_s = 0.001;
  double poll_marking_s = 0.010;
};

// `--trigger lmc-input:BIT` (BIT 0–15). InputError naming the option and the range otherwise.
int parse_board_trigger(std::string_view text, std::string_view option);
// `--signal ready=B,busy=B,done=B,error=B`: any subset in any order, each name once, B 0–15,
// no bit twice. InputError naming the option, the item and the range otherwise.
BoardSignals parse_board_signals(std::string_view text, std::string_view option);

// One input pin's edges, sample by sample (no clock of its own: the tests give the times).
// Debounce: the level counts as changed once the pin has held it for `debounce_s`; so a bounce
// train shorter than that is one edge. A rising edge fires once the debounced level has been
// high for `min_pulse_s` since the pin rose (so it fires max(debounce, min_pulse) after the
// rise); a shorter pulse fires nothing. A pin already high at the first sample is no edge.
class TriggerFilter {
 public:
  TriggerFilter(double debounce_s, double min_pulse_s) : debounce_s_(debounce_s), min_pulse_s_(min_pulse_s) {}
  // True once per qualifying pulse, at the sample that qualifies it. `t_s` must not decrease.
  bool sample(bool high, double t_s);
  bool level() const { return stable_; }  // the debounced level

 private:
  double debounce_s_, min_pulse_s_;
  bool primed_ = false;
  bool candidate_ = false, stable_ = false, fired_ = true;
  double candidate_since_s_ = 0, stable_since_s_ = 0;
};

class BoardIo {
 public:
  // Sets the outputs for the station's state now and starts polling. `log` gets one line per
  // event (may be empty).
  BoardIo(Station& station, BoardPort port, BoardIoOptions options,
          std::function<void(const std::string&)> log = {});
  ~BoardIo();  // stop()
  BoardIo(const BoardIo&) = delete;
  BoardIo& operator=(const BoardIo&) = delete;

  // No trigger and no output change from now on (the poller's thread ends; the station's
  // events reach nothing). The outputs stay as last written.
  void stop();

  std::uint64_t triggers() const { return triggers_.load(); }  // marks started by the input
  std::uint64_t ignored() const { return ignored_.load(); }    // edges the station refused

 private:
  // What the station's listener and the poller share; the listener holds it by shared_ptr, so
  // an event after stop() (the station outlives this) finds it detached and does nothing.
  struct Shared {
    std::mutex mutex;
    std::condition_variable wake;
    bool detached = false;
    bool outputs_dirty = false;
    StationState state = StationState::idle;
    std::optional<PartResult> last;  // the last part that ended, for the done light
    BoardSignals signals;
    std::function<void(std::uint16_t)> set_outputs;
  };
  static void on_event(Shared& shared, const StationEvent& event);  // the station's lock is held
  void run();
  void poll_input(TriggerFilter& filter, double t_s);
  bool flush_outputs();  // false: the board did not take them
  void emit(const std::string& line) const;

  Station& station_;
  BoardPort port_;
  BoardIoOptions options_;
  std::function<void(const std::string&)> log_;
  std::shared_ptr<Shared> shared_;
  bool read_failing_ = false, write_failing_ = false;  // the poller's thread only
  std::atomic<std::uint64_t> triggers_{0}, ignored_{0};
  std::thread poller_;
};

}  // namespace mark
