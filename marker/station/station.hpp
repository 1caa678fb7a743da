#pragma once
// The marking station's one state machine (issue 22), behind every interface (the TCP line
// protocol today; HTTP, Modbus and board I/O are adapters of the same calls):
//
//   idle ──mark──► marking ──part ends done / aborted──► idle
//                     └──part failed (device fault)───► error ──reset──► idle
//   idle ──pause──► paused ──resume──► idle
//
// A trigger while marking is refused `busy`, never queued: a PLC that triggers twice must see
// it. abort() works in every state and from any thread: the stop flag and the device's own
// abort() put the laser out at once; a part in progress ends aborted and is recorded as the
// store records aborted parts (its numbers void). Nothing here does I/O: the parts come from a
// PartSource (the job on the device and the store: marker/cli/serve_source.hpp) and events go
// to a listener (the server logs them).
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "marker/production/part_run.hpp"
#include "ringbuffer/stop_flag.hpp"

namespace mark {

enum class StationState { idle, marking, paused, error };
std::string_view to_string(StationState state);

// What the station marks: a job on a device, with its store. Only one call at a time: the
// station never calls it concurrently, except abort_device() (any thread, any time).
class PartSource {
 public:
  virtual ~PartSource() = default;
  // The next part: allocate, mark, record (PartRunner::mark_next). `stop` is the station's.
  // Throws InputError for a refusal before anything was consumed.
  virtual PartResult mark_next(const StopFlag& stop) = 0;
  virtual void abort_device() noexcept = 0;  // laser off now
  virtual void reset_device() = 0;           // a failed device re-armed
  // Throws InputError for a variable no template uses or a value the job cannot mark.
  virtual void set_variable(const std::string& name, const std::string& value) = 0;
  // The next part's texts and serial values; nothing consumed.
  virtual std::vector<ObjectText> preview(std::map<std::string, std::int64_t>* serials) = 0;
  // The next part's picture (PNG), nothing consumed; a source without one throws InputError.
  virtual std::string preview_png();
  // The value the next part gets from `counter`; nothing when it has stopped. Throws
  // InputError for a counter the job does not use.
  virtual std::optional<std::int64_t> next_serial(const std::string& counter) = 0;
  // Another job file on the same device and store. Throws InputError and keeps the old one.
  virtual void load(const std::string& job) = 0;
  virtual std::string job() const = 0;
  // The store's audit log, as `marker log` reads it: matching rows in id order, `row` returns
  // false to stop. Must not wait for a part being marked (a read-only snapshot of its own), so
  // the station calls it at any time; a source without a log throws InputError.
  virtual void read_log(const AuditFilter& filter, const std::function<bool(const AuditRow&)>& row);
};

// A refused or failed request: `code` is one word (busy, paused, error, refused, …).
struct StationError {
  std::string code;
  std::string message;
};

// What a mark request gives: the part (whatever outcome PartRunner gave), or why none ran.
struct MarkAttempt {
  std::optional<PartResult> part;
  std::optional<StationError> error;
};

// What an interface that pushes events (the HTTP event stream) is told: the state the station
// entered, or a part that ended (its state change follows as its own event).
struct StationEvent {
  StationState state = StationState::idle;
  std::optional<PartResult> part;  // set: a part ended (state: the state it ended in)
};

// The handshake every interface shows a PLC (Modbus discrete inputs 0–3, the board's output
// bits): ready = idle (a start would mark), busy = marking, done = not marking and the last part
// ended done (a level, cleared when the next part starts), error = in error (needs a reset).
struct StationLights {
  bool ready = false, busy = false, done = false, error = false;
};
StationLights station_lights(StationState state, const std::optional<PartResult>& last);

struct StationStatus {
  StationState state = StationState::idle;
  std::string job;
  std::uint64_t parts = 0;  // parts that ran since start, by outcome below
  std::map<std::string, std::uint64_t> outcomes;
  std::optional<PartResult> last;
  std::string error;  // state error: why
};

class Station {
 public:
  // `source` outlives the station; `log` gets one line per event (may be empty).
  Station(PartSource& source, std::function<void(const std::string&)> log = {});
  ~Station();  // waits for an asynchronous mark
  Station(const Station&) = delete;
  Station& operator=(const Station&) = delete;

  // One part now, on the caller's thread; refused busy / paused / error without waiting.
  MarkAttempt mark();
  // One part on the station's own thread; returns once it started (or why not).
  std::optional<StationError> mark_async();
  // Laser off now, in any state; a running part ends aborted. Returns the state it met.
  StationState abort();
  std::optional<StationError> pause();
  std::optional<StationError> resume();
  std::optional<StationError> reset();
  // Refused busy while marking (the source is in use).
  std::optional<StationError> set_variable(const std::string& name, const std::string& value);
  std::optional<StationError> load(const std::string& job);
  // The next part's texts and values (nothing consumed), or why not.
  std::optional<StationError> preview(std::vector<ObjectText>& texts,
                                      std::map<std::string, std::int64_t>& serials);
  std::optional<StationError> next_serial(const std::string& counter, std::optional<std::int64_t>& next);
  // The next part's picture (PNG; PartSource::preview_png), or why not.
  std::optional<StationError> preview_png(std::string& png);

  // The store's audit log (PartSource::read_log), at any time: never waits for a part.
  void read_log(const AuditFilter& filter, const std::function<bool(const AuditRow&)>& row);
  // `listener` is told every state change and every part that ended, in order, from the thread
  // that caused it and under the station's lock: it must return quickly and not call back.
  void add_listener(std::function<void(const StationEvent&)> listener);

  StationStatus status() const;
  // Blocks until no part runs (an asynchronous one included).
  void wait_idle();

 private:
  std::optional<StationError> begin();  // idle → marking, under the lock
  MarkAttempt run();                    // the part, then marking → idle / error
  std::optional<StationError> refuse_unless_still() const;  // lock held
  std::optional<StationError> hold(StationState to);        // pause / resume
  void emit(const std::string& line) const;
  void notify(const StationEvent& event) const;  // lock held
  void enter(StationState to);                   // lock held: the state, logged and notified

  PartSource& source_;
  std::function<void(const std::string&)> log_;
  std::vector<std::function<void(const StationEvent&)>> listeners_;
  mutable std::mutex mutex_;
  std::condition_variable ended_;
  StationState state_ = StationState::idle;
  StationStatus counts_;
  StopFlag stop_;
  std::thread async_;
};

}  // namespace mark
