#pragma once
// The serial store: never repeat a number or a marked text, never lose one, and a log that is
// right about every part. One part's life:
//
//   allocate()        one transaction: lock the job's counters (in name order; each must have
//                     been created), take() the next value of each in the current period
//                     (periods only move forward), take the next data-list row not taken
//                     before, render the objects' texts and refuse the part when a text that
//                     carries a serial field was marked before; write the counters back and
//                     record the values, the row and the texts with the audit row — committed
//                     durably before it returns, so before the first sample reaches the device;
//   (the mark runs)
//   record_outcome()  done, aborted or failed, with the device's figures: first into the
//                     station's outcome journal (flushed), then into the store, tried again on
//                     a locked store or a lost connection. When the store cannot take it the
//                     journal keeps it, and the next start (or the next allocation) replays it.
//                     An aborted or failed part's numbers and data row are void for good.
//
// A process that dies between the two leaves a row without an outcome; the next start of that
// station (start_station) replays its journal and records what is still open as aborted. A
// re-mark is its own audit row that links the first mark and consumes nothing.
//
// The store never prints: what it noticed comes back in its results (notes, ids), and every
// refusal is an exception with one line that says what to do.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "marker/store/outcome_journal.hpp"
#include "marker/store/store_backend.hpp"
#include "marker/vars/counter.hpp"
#include "marker/vars/data_list.hpp"
#include "marker/vars/shifts.hpp"

namespace mark {

// Who marks what, when.
struct MarkContext {
  std::string station = "station";
  std::string job;         // path as given
  std::string job_sha256;
  SysTime now{};
};

// How hard the store tries before it gives up on a step.
struct RetryPolicy {
  int attempts = 3;            // of an allocation (locked store, lost connection) and an outcome
  int first_delay_ms = 200;    // between attempts, doubling up to max_delay_ms
  int max_delay_ms = 2000;
};

struct StoreSettings {
  RetryPolicy retry;
  // The folder of the outcome journals; empty: no journal (an outcome the store cannot take
  // then throws).
  std::string journal_dir;
  // A count that grows with every cancel request (Ctrl-C); a wait of the store (a lock, the
  // server, a pause between attempts) ends when it changes during the wait.
  std::function<std::uint64_t()> interrupts;
  // Fault injection (store_faults.hpp): nothing in production.
  std::optional<StoreFaultPlan> fault;
};

// A part's data-list row: the list and the first row it may take (the rows before it were
// taken by this run already). The store takes the first row from `from` on that no part has.
struct DataPick {
  const DataList* list = nullptr;
  std::string name;        // the file as the job names it, for the audit row
  std::size_t from = 0;
};

// What one part consumes, and when it is dated.
struct PartValues {
  std::map<std::string, std::int64_t> serials;
  std::optional<std::size_t> data_row;  // index into the data list
  // The instant the part's date and shift fields render: the clock, or — when the clock stands
  // behind a counter's period (stepped back across a reset) — the start of that period, so the
  // part is dated in the period its number belongs to and its text cannot meet an earlier one.
  SysTime now{};
};

struct Allocation {
  std::int64_t mark_id = 0;
  std::map<std::string, Issue> issues;  // by counter name
  std::map<std::string, std::int64_t> serials;
  std::optional<std::size_t> data_row;  // index into the data list (row number − 1)
  std::vector<ObjectText> objects;
  std::string time_utc;
  std::string note;  // e.g. the clock stood behind a counter's period (kept in the audit row)
  std::optional<std::int64_t> remark_of;  // a re-mark: the part's first mark
};

// Renders every object's text from the values a part consumed. Called inside the allocation
// transaction: if it throws, nothing is consumed and nothing is logged.
using RenderObjects =
    std::function<std::vector<ObjectText>(const std::map<std::string, std::int64_t>& serials)>;
using RenderPart = std::function<std::vector<ObjectText>(const PartValues& values)>;

struct CounterStatus {
  std::string name;
  CounterState state;                 // as stored
  std::optional<std::int64_t> next;   // what the next part gets (with a spec: after the reset
                                      // and limit rules; nothing when the counter has stopped)
  std::optional<std::int64_t> highest_issued;  // in the current period and cycle
  std::optional<std::int64_t> lowest_issued;
  bool known = false;                 // the store has the counter
};

// What a station's start found.
struct StationStart {
  std::vector<std::int64_t> replayed;  // outcomes the journal held, now in the store
  std::vector<std::int64_t> closed;    // rows left open, recorded aborted (numbers void)
  std::vector<std::string> notes;      // journal entries that did not match their row, …
};

// How a part's outcome was recorded.
struct OutcomeWrite {
  bool stored = false;     // in the store
  bool journaled = false;  // in the journal (replayed at the next start when not stored)
  int attempts = 0;        // store writes tried
  std::string error;       // why the store did not take it
  std::string journal;     // the journal's file
};

// Refusals of a part before the laser fires (nothing consumed): a counter the store does not
// know, a text marked before, a value issued before, a data list used up.
class PartRefused : public InputError {
 public:
  using InputError::InputError;
};

class SerialStore {
 public:
  explicit SerialStore(std::unique_ptr<StoreBackend> backend, StoreSettings settings = {});
  ~SerialStore();

  const StoreBackend& backend() const { return *backend_; }
  std::string describe() const { return backend_->describe(); }
  // The journal of the station started, if any.
  const OutcomeJournal* journal() const { return journal_.get(); }

  // Claims the station name (throws StoreError if another process marks as this station on
  // this store file, however reached), checks the store (PRAGMA quick_check; a damaged store
  // is refused), replays the station's outcome journal and closes the rows a dead process of
  // this station left open: outcome aborted, numbers void.
  StationStart start_station(const MarkContext& ctx);

  // Creates counter `name` with its next value `start` in reset period `period` (a counter
  // exists only once created, so a renamed counter or a typo never starts at 1 unnoticed).
  // Throws InputError when it exists. An audit row records it.
  void create_counter(const std::string& name, std::int64_t start, const std::string& period,
                      const MarkContext& ctx);
  // Creates the counters of `counters` the store does not know, each at its start in the
  // current period; returns their names.
  std::vector<std::string> create_missing(const std::map<std::string, CounterSpec>& counters,
                                          const ShiftTable& shifts, const MarkContext& ctx);

  // The counters a part consumes (each once, whatever the number of fields using it).
  Allocation allocate(const std::map<std::string, CounterSpec>& counters, const ShiftTable& shifts,
                      const MarkContext& ctx, const RenderObjects& render);
  Allocation allocate(const std::map<std::string, CounterSpec>& counters, const ShiftTable& shifts,
                      const MarkContext& ctx, const DataPick& data, const RenderPart& render);
  OutcomeWrite record_outcome(std::int64_t mark_id, const OutcomeRecord& outcome);
  // A new audit row with the texts and values of `original` (a mark or re-mark of this store),
  // linked to the first mark. Consumes nothing. A part that ended done and was re-marked
  // already is re-marked again only with a `reason`, which the row keeps.
  // A part marked with another version of the job file is refused unless `allow_changed_job`;
  // then the new row carries this job's hash and a note naming the one the part was marked with.
  Allocation remark(std::int64_t original, const MarkContext& ctx, const std::string& reason = "",
                    bool allow_changed_job = false);

  // The data-list row the next part would take (read-only; nothing: every row is taken).
  std::optional<std::size_t> next_data_row(const DataPick& data);

  // With a spec, `next` follows its rules at `now`; without, it is the stored next value.
  // Read-only.
  CounterStatus status(const std::string& name, const CounterSpec* spec, const ShiftTable& shifts,
                       SysTime now);
  // Makes `value` the next value of the counter (in the current period and cycle). Refused
  // (InputError) when a value at or past it in counting direction was issued there already.
  void set(const CounterSpec& spec, std::int64_t value, const ShiftTable& shifts,
           const MarkContext& ctx);
  // Issues `count` values without marking (labels printed elsewhere, a spare station). One
  // audit row per value, outcome reserved.
  std::vector<Issue> reserve(const CounterSpec& spec, std::int64_t count, const ShiftTable& shifts,
                             const MarkContext& ctx);

  // Streams the audit rows the filter selects (read-only, constant memory).
  void read_log(const AuditFilter& filter, const std::function<bool(const AuditRow&)>& row);
  // The whole log (tests, small stores).
  std::vector<AuditRow> log(const std::string& since_utc = "");
  std::vector<std::pair<std::string, CounterState>> counters();
  std::vector<std::pair<Issue, std::int64_t>> issues(const std::string& counter);
  // The store's own check (`quick`: PRAGMA quick_check; else integrity_check and foreign keys)
  // and the store's rules: every counter's next value lies past what it issued. Problems, one
  // a line; empty when sound.
  std::vector<std::string> check(bool quick);

 private:
  // Runs one attempt after another of a step (retry policy, fault plan, reconnect, cancel).
  void run_step(StoreStep step, const std::function<void()>& once);
  template <class F>
  auto attempt(StoreStep step, F&& once) -> decltype(once()) {
    std::optional<decltype(once())> out;
    run_step(step, [&] { out.emplace(once()); });
    return std::move(*out);
  }
  void pause(int attempt, std::uint64_t interrupts_at_start);
  std::uint64_t interrupts() const;
  // Outcomes the journal holds that the store has not: into the store. Ids replayed.
  std::vector<std::int64_t> replay(std::vector<std::string>* notes);

  std::unique_ptr<StoreBackend> backend_;
  StoreSettings settings_;
  std::unique_ptr<OutcomeJournal> journal_;
  std::map<StoreStep, int> calls_;  // per step, for the fault plan
  // Rows allocated by this process and not yet recorded: their values and text go into the
  // journal with the outcome, so a replay checks it meets the same row.
  std::map<std::int64_t, JournalEntry> open_rows_;
};

}  // namespace mark
