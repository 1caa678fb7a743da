#pragma once
// What a serial store backend provides: durable transactions over the store's tables (counters,
// marks = the audit log, issues, outcomes, the marked texts, the data rows taken; docs/store.md
// has the schema), and read-only transactions that never block a writer. The rules — which
// value a part gets, what may be set, when a text repeats — live in SerialStore above this, once
// for every backend.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "marker/store/audit_row.hpp"
#include "marker/store/store_error.hpp"
#include "marker/store/store_faults.hpp"
#include "marker/vars/counter.hpp"

namespace mark {

// Which audit rows a reader wants. Every condition given must hold.
struct AuditFilter {
  std::string since_utc;               // allocated at or after (empty: from the first)
  std::optional<std::int64_t> limit;   // only the last N matching rows (still printed in id order)
  std::optional<std::int64_t> value;   // rows that consumed this counter value (and their re-marks)
  std::string counter;                 // … of this counter (empty: any)
  std::optional<std::string> text;     // rows that marked exactly this text in an object carrying
                                       // a serial field (and their re-marks)
  std::string job;                     // rows marked with this job file (its path as recorded)
};

// A re-mark of a row and how it ended (nothing: pending).
struct RemarkRow {
  std::int64_t id = 0;
  std::optional<Outcome> outcome;
};

// A read-only view: SQLite reads a snapshot (WAL: a writer is never blocked by it), PostgreSQL
// a REPEATABLE READ READ ONLY transaction. Ends (rolled back) when destroyed.
class StoreReader {
 public:
  virtual ~StoreReader() = default;

  // Streams the matching rows in id order, one at a time (constant memory whatever the size
  // of the log), each with its outcome and issues. `row` returns false to stop early.
  virtual void audit(const AuditFilter& filter, const std::function<bool(const AuditRow&)>& row) = 0;
  virtual std::optional<AuditRow> audit_row(std::int64_t id) = 0;
  // The counter's stored state; nothing when the store does not know it.
  virtual std::optional<CounterState> counter(const std::string& name) = 0;
  // Every counter the store holds, by name.
  virtual std::vector<std::pair<std::string, CounterState>> counters() = 0;
  // Every issue of a counter with the row it belongs to, streamed.
  virtual void issues(const std::string& counter,
                      const std::function<void(const Issue&, std::int64_t mark_id)>& each) = 0;
  // Lowest and highest value issued in (counter, period, cycle); nothing if none.
  virtual std::optional<std::pair<std::int64_t, std::int64_t>> issued_range(
      const std::string& counter, const std::string& period, std::int64_t cycle) = 0;
  // The row that holds this issue (counter, period, cycle, value, repeat), if any.
  virtual std::optional<std::int64_t> issue_owner(const Issue& issue) = 0;
  // The row that marked this text in an object carrying a serial field, if any.
  virtual std::optional<std::int64_t> text_owner(const std::string& text) = 0;
  // The row that took the data-list row with this identity (a SHA-256), if any.
  virtual std::optional<std::int64_t> data_row_owner(const std::string& key) = 0;
  // The re-marks of row `original`, oldest first.
  virtual std::vector<RemarkRow> remarks_of(std::int64_t original) = 0;
};

// One write transaction. Destroying it without commit() rolls everything back.
class StoreTransaction : public StoreReader {
 public:
  // The counter's state, locked against other writers until the transaction ends; nothing when
  // the store does not know the counter (counters exist only once created).
  virtual std::optional<CounterState> lock_counter(const std::string& name) = 0;
  // Creates a counter; throws StoreError (constraint) if it exists.
  virtual void create_counter(const std::string& name, const CounterState& state) = 0;
  // Writes the state back (UPDATE … RETURNING: throws StoreError if the row did not change).
  virtual void update_counter(const std::string& name, const CounterState& state) = 0;
  // Appends an audit row; returns its id (ids only grow and are never reused).
  virtual std::int64_t insert_mark(const MarkRecord& mark) = 0;
  // Records one consumed value. The key (counter, period, cycle, value, repeat) makes a second
  // issue of the same value fail: throws StoreError (constraint).
  virtual void insert_issue(const Issue& issue, std::int64_t mark_id) = 0;
  // Appends the outcome of a row; a second outcome for the same row throws StoreError.
  virtual void insert_outcome(std::int64_t mark_id, const OutcomeRecord& outcome) = 0;
  // Records a marked text (unique: a second row with the same text throws StoreError).
  virtual void insert_text(const std::string& text, const std::string& object, std::int64_t mark_id) = 0;
  // Serialises the stations taking rows of one data list (PostgreSQL: an advisory lock until
  // the transaction ends; SQLite holds the write lock already).
  virtual void lock_data_list(const std::string& list_key) = 0;
  // Records a data-list row taken (unique by key).
  virtual void insert_data_row(const std::string& key, const std::string& list, std::int64_t row,
                               std::int64_t mark_id) = 0;
  // Rows of this station without an outcome, oldest first.
  virtual std::vector<std::int64_t> pending_marks(const std::string& station) = 0;
  // Makes everything durable (SQLite: WAL fsync; PostgreSQL: the server's commit).
  virtual void commit() = 0;
};

class StoreBackend {
 public:
  virtual ~StoreBackend() = default;
  virtual std::unique_ptr<StoreTransaction> begin() = 0;
  virtual std::unique_ptr<StoreReader> begin_read() = 0;
  // "sqlite:/path/to/file" or "postgresql://user@host:port/db" (without a password).
  virtual std::string describe() const = 0;
  // A random identity written when the store was created: the outcome journal is keyed on it.
  virtual const std::string& store_id() const = 0;
  // Exclusive use of a station name while this backend lives (one marking process per station
  // and store, however the store was reached). False when another process holds it.
  virtual bool claim_station(const std::string& station) = 0;
  // The store's own consistency check: `quick` at every station start (SQLite: PRAGMA
  // quick_check), else the full one (integrity_check and foreign keys). Problems, one a line;
  // empty when sound.
  virtual std::vector<std::string> check(bool quick) = 0;
  // After a lost connection: connect again (and take back the claimed station names). Throws
  // StoreError when the server cannot be reached.
  virtual void reconnect() = 0;
  // Waits for a lock or a server (a busy store, a lock timeout) end early, with a StoreError of
  // kind cancelled, once `cancel` returns true (polled every few milliseconds).
  virtual void set_cancel(std::function<bool()> cancel) = 0;
  // Fault injection (tests and --inject store@STEP:KIND): makes the fault happen for real on the
  // next transaction of `step` (a second connection holding the lock, the disk reporting full,
  // the connection terminated), until heal(). Throws StoreError when the backend cannot
  // produce this kind.
  virtual void provoke(StoreStep step, StoreFaultKind kind) = 0;
  virtual void heal() = 0;
};

}  // namespace mark
