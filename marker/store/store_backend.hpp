#pragma once
// What a serial store backend provides: durable transactions over four tables (counters,
// marks = the audit log, issues, outcomes; docs/store.md has the schema). The rules — which
// value a part gets, what may be set — live in SerialStore above this, once for every backend.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "marker/store/audit_row.hpp"
#include "marker/vars/counter.hpp"

namespace mark {

// A store that cannot be opened, read or written (the message names the store).
class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One write transaction. Destroying it without commit() rolls everything back.
class StoreTransaction {
 public:
  virtual ~StoreTransaction() = default;

  // The counter's state, locked against other writers until the transaction ends; a counter
  // the store has never seen is created with `initial` first.
  virtual CounterState lock_counter(const std::string& name, const CounterState& initial) = 0;
  // Writes the state back (UPDATE … RETURNING: throws StoreError if the row did not change).
  virtual void update_counter(const std::string& name, const CounterState& state) = 0;
  // Appends an audit row; returns its id (ids only grow and are never reused).
  virtual std::int64_t insert_mark(const MarkRecord& mark) = 0;
  // Records one consumed value. The store's key (counter, period, cycle, value, repeat) makes a
  // second issue of the same value fail: throws StoreError.
  virtual void insert_issue(const Issue& issue, std::int64_t mark_id) = 0;
  // Appends the outcome of a row; a second outcome for the same row throws StoreError.
  virtual void insert_outcome(std::int64_t mark_id, const OutcomeRecord& outcome) = 0;
  // Lowest and highest value issued in (counter, period, cycle); nothing if none.
  virtual std::optional<std::pair<std::int64_t, std::int64_t>> issued_range(
      const std::string& counter, const std::string& period, std::int64_t cycle) = 0;
  // Rows of this station without an outcome, oldest first.
  virtual std::vector<std::int64_t> pending_marks(const std::string& station) = 0;
  // Audit rows with time_utc ≥ since (all when empty), by id; or one row.
  virtual std::vector<AuditRow> audit(const std::string& since_utc) = 0;
  virtual std::optional<AuditRow> audit_row(std::int64_t id) = 0;
  // Every counter the store holds (no lock).
  virtual std::vector<std::pair<std::string, CounterState>> counters() = 0;
  // Every issue of a counter, for checks and reports.
  virtual std::vector<std::pair<Issue, std::int64_t>> issues(const std::string& counter) = 0;
  // Makes everything durable (SQLite: WAL fsync; PostgreSQL: the server's commit).
  virtual void commit() = 0;
};

class StoreBackend {
 public:
  virtual ~StoreBackend() = default;
  virtual std::unique_ptr<StoreTransaction> begin() = 0;
  // "sqlite:/path/to/file" or "postgresql://host/db" (without a password), for messages.
  virtual std::string describe() const = 0;
  // Exclusive use of a station name while this backend lives (one marking process per station
  // and store). False when another process holds it.
  virtual bool claim_station(const std::string& station) = 0;
};

}  // namespace mark
