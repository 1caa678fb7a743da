#include "marker/store/sqlite_backend.hpp"

#include <unistd.h>

#include <filesystem>

#include "marker/store/row_codec.hpp"
#include "marker/store/sqlite_db.hpp"
#include "marker/store/sqlite_fault_vfs.hpp"
#include "marker/store/sqlite_schema.hpp"
#include "marker/store/station_lock.hpp"

namespace mark {
namespace {

// An audit row in kAuditColumns order, with the values it consumed (a re-mark: its original's).
std::string audit_select(int version) {
  const char* v2 = "m.reason, m.note, m.data_list, m.data_row, ";
  const char* v1 = "'', '', NULL, NULL, ";
  return std::string("SELECT m.id, m.time_utc, m.station, m.job, m.job_sha256, m.kind, m.remark_of, "
                     "m.objects, m.serials, ") +
         (version >= 2 ? v2 : v1) +
         "o.time_utc, o.outcome, o.message, o.figures, "
         "(SELECT json_group_array(json_array(i.counter, i.period, i.cycle, i.value, i.repeat)) "
         "FROM issues i WHERE i.mark_id = COALESCE(m.remark_of, m.id)) "
         "FROM marks m LEFT JOIN outcomes o ON o.mark_id = m.id ";
}

// Parameters: ?1 since, ?2 value, ?3 counter, ?4 text, ?5 limit, ?6 job.
std::string audit_query(const AuditFilter& f, int version) {
  std::string where;
  const auto add = [&](const std::string& cond) { where += (where.empty() ? "WHERE " : " AND ") + cond; };
  // The time index finds the first part since then, and the scan starts at its id: without the
  // id bound SQLite reads every row in id order (3.3 s for 1000 rows of a 10 M-row store). Exact
  // even when the clock went back: every row at or after ?1 has an id at or above that minimum,
  // and the time condition drops the older rows between. INDEXED BY because the planner would
  // otherwise take MIN(id) by walking the ids up from the first until one is late enough.
  if (!f.since_utc.empty())
    add("m.id >= (SELECT MIN(id) FROM marks INDEXED BY marks_time WHERE time_utc >= ?1) AND m.time_utc >= ?1");
  if (f.value) {
    const std::string issued =
        "SELECT mark_id FROM issues WHERE value = ?2" + std::string(f.counter.empty() ? "" : " AND counter = ?3");
    add("(m.id IN (" + issued + ") OR m.remark_of IN (" + issued + "))");
  }
  if (f.text) {
    if (version >= 2)
      add("(m.id IN (SELECT mark_id FROM marked_texts WHERE text = ?4) OR "
          "m.remark_of IN (SELECT mark_id FROM marked_texts WHERE text = ?4))");
    else
      add("EXISTS (SELECT 1 FROM json_each(m.objects) j WHERE json_extract(j.value, '$.text') = ?4)");
  }
  if (!f.job.empty()) add("m.job = ?6");
  const std::string select = audit_select(version) + where;
  if (f.limit) return "SELECT * FROM (" + select + " ORDER BY m.id DESC LIMIT ?5) ORDER BY 1";
  return select + " ORDER BY m.id";
}

CounterState state_from(const SqliteStmt& q, int first) {
  CounterState s;
  s.next = q.i64(first);
  s.used = q.i64(first + 1);
  s.period = q.text(first + 2);
  s.cycle = q.i64(first + 3);
  s.exhausted = q.i64(first + 4) != 0;
  return s;
}

// The reading half, shared by read-only and write transactions.
template <class Base>
class SqliteReading : public Base {
 public:
  SqliteReading(const SqliteDb& db, int version) : db_(db), version_(version) {}

  void audit(const AuditFilter& f, const std::function<bool(const AuditRow&)>& row) override {
    SqliteStmt s(db_, audit_query(f, version_));
    if (!f.since_utc.empty()) s.bind(1, f.since_utc);
    if (f.value) s.bind(2, *f.value);
    if (!f.counter.empty()) s.bind(3, f.counter);
    if (f.text) s.bind(4, *f.text);
    if (f.limit) s.bind(5, *f.limit);
    if (!f.job.empty()) s.bind(6, f.job);
    while (s.step())
      if (!row(decode(s))) break;
  }

  std::optional<AuditRow> audit_row(std::int64_t id) override {
    SqliteStmt s(db_, audit_select(version_) + "WHERE m.id = ?1");
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return decode(s);
  }

  std::optional<CounterState> counter(const std::string& name) override {
    SqliteStmt q(db_, "SELECT next_value, used, period, cycle, exhausted FROM counters WHERE name = ?1");
    q.bind(1, name);
    if (!q.step()) return std::nullopt;
    return state_from(q, 0);
  }

  std::vector<std::pair<std::string, CounterState>> counters() override {
    SqliteStmt s(db_, "SELECT name, next_value, used, period, cycle, exhausted FROM counters ORDER BY name");
    std::vector<std::pair<std::string, CounterState>> out;
    while (s.step()) out.emplace_back(s.text(0), state_from(s, 1));
    return out;
  }

  void issues(const std::string& counter,
              const std::function<void(const Issue&, std::int64_t)>& each) override {
    SqliteStmt s(db_, "SELECT period, cycle, value, repeat, mark_id FROM issues WHERE counter = ?1 "
                      "ORDER BY mark_id, value");
    s.bind(1, counter);
    while (s.step()) each(Issue{counter, s.i64(2), s.i64(3), s.text(0), s.i64(1)}, s.i64(4));
  }

  std::optional<std::pair<std::int64_t, std::int64_t>> issued_range(
      const std::string& counter, const std::string& period, std::int64_t cycle) override {
    SqliteStmt s(db_, "SELECT MIN(value), MAX(value) FROM issues WHERE counter = ?1 AND period = ?2 "
                      "AND cycle = ?3");
    s.bind(1, counter).bind(2, period).bind(3, cycle);
    if (!s.step() || s.null(0)) return std::nullopt;
    return std::make_pair(s.i64(0), s.i64(1));
  }

  std::optional<std::int64_t> issue_owner(const Issue& i) override {
    SqliteStmt s(db_, "SELECT mark_id FROM issues WHERE counter = ?1 AND period = ?2 AND cycle = ?3 "
                      "AND value = ?4 AND repeat = ?5");
    s.bind(1, i.counter).bind(2, i.period).bind(3, i.cycle).bind(4, i.value).bind(5, i.repeat);
    return one(s);
  }

  std::optional<std::int64_t> text_owner(const std::string& text) override {
    if (version_ < 2) return std::nullopt;
    SqliteStmt s(db_, "SELECT mark_id FROM marked_texts WHERE text = ?1");
    s.bind(1, text);
    return one(s);
  }

  std::optional<std::int64_t> data_row_owner(const std::string& key) override {
    if (version_ < 2) return std::nullopt;
    SqliteStmt s(db_, "SELECT mark_id FROM data_rows WHERE row_key = ?1");
    s.bind(1, key);
    return one(s);
  }

  std::vector<RemarkRow> remarks_of(std::int64_t original) override {
    SqliteStmt s(db_, "SELECT m.id, o.outcome FROM marks m LEFT JOIN outcomes o ON o.mark_id = m.id "
                      "WHERE m.remark_of = ?1 AND m.kind = 'remark' ORDER BY m.id");
    s.bind(1, original);
    std::vector<RemarkRow> out;
    while (s.step()) {
      RemarkRow r{s.i64(0), std::nullopt};
      if (!s.null(1)) r.outcome = parse_outcome(s.text(1));
      out.push_back(r);
    }
    return out;
  }

 protected:
  static std::optional<std::int64_t> one(SqliteStmt& s) {
    if (!s.step()) return std::nullopt;
    return s.i64(0);
  }
  AuditRow decode(const SqliteStmt& s) const {
    return audit_row_from(
        [&](int c) -> std::optional<std::string> {
          if (s.null(c)) return std::nullopt;
          return s.text(c);
        },
        db_.name());
  }

  const SqliteDb& db_;
  int version_;
};

// A snapshot: BEGIN (deferred) takes no lock until the first read, and in WAL mode a reader's
// snapshot never blocks a writer, nor a writer the reader.
class SqliteReader final : public SqliteReading<StoreReader> {
 public:
  SqliteReader(const SqliteDb& db, int version) : SqliteReading(db, version) { db.exec("BEGIN"); }
  ~SqliteReader() override { sqlite3_exec(db_.get(), "ROLLBACK", nullptr, nullptr, nullptr); }
};

class SqliteTransaction final : public SqliteReading<StoreTransaction> {
 public:
  SqliteTransaction(const SqliteDb& db, int version) : SqliteReading(db, version) {
    // IMMEDIATE: the write lock is taken now, so two writers never both read a counter and
    // then race to update it.
    db_.exec("BEGIN IMMEDIATE");
  }
  ~SqliteTransaction() override {
    if (!done_) sqlite3_exec(db_.get(), "ROLLBACK", nullptr, nullptr, nullptr);
  }

  std::optional<CounterState> lock_counter(const std::string& name) override { return counter(name); }

  void create_counter(const std::string& name, const CounterState& s) override {
    SqliteStmt ins(db_, "INSERT INTO counters(name, next_value, used, period, cycle, exhausted) "
                        "VALUES(?1, ?2, ?3, ?4, ?5, ?6)");
    ins.bind(1, name).bind(2, s.next).bind(3, s.used).bind(4, s.period).bind(5, s.cycle)
        .bind(6, std::int64_t{s.exhausted});
    ins.finish();
  }

  void update_counter(const std::string& name, const CounterState& s) override {
    SqliteStmt u(db_, "UPDATE counters SET next_value = ?2, used = ?3, period = ?4, cycle = ?5, "
                      "exhausted = ?6 WHERE name = ?1 RETURNING next_value");
    u.bind(1, name).bind(2, s.next).bind(3, s.used).bind(4, s.period).bind(5, s.cycle)
        .bind(6, std::int64_t{s.exhausted});
    if (!u.step() || u.i64(0) != s.next)
      throw StoreError("serial store " + db_.name() + ": counter '" + name + "' was not updated");
    u.finish();
  }

  std::int64_t insert_mark(const MarkRecord& m) override {
    SqliteStmt s(db_, "INSERT INTO marks(time_utc, station, job, job_sha256, kind, remark_of, objects, "
                      "serials, reason, note, data_list, data_row) "
                      "VALUES(?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12) RETURNING id");
    s.bind(1, m.time_utc).bind(2, m.station).bind(3, m.job).bind(4, m.job_sha256)
        .bind(5, std::string(to_string(m.kind)));
    m.remark_of ? s.bind(6, *m.remark_of) : s.bind_null(6);
    s.bind(7, objects_to_json(m.objects)).bind(8, serials_to_json(m.serials)).bind(9, m.reason)
        .bind(10, m.note);
    m.data_list.empty() ? s.bind_null(11) : s.bind(11, m.data_list);
    m.data_row ? s.bind(12, *m.data_row) : s.bind_null(12);
    if (!s.step()) throw StoreError("serial store " + db_.name() + ": audit row not written");
    const std::int64_t id = s.i64(0);
    s.finish();
    return id;
  }

  void insert_issue(const Issue& i, std::int64_t mark_id) override {
    SqliteStmt s(db_, "INSERT INTO issues(counter, period, cycle, value, repeat, mark_id) "
                      "VALUES(?1, ?2, ?3, ?4, ?5, ?6)");
    s.bind(1, i.counter).bind(2, i.period).bind(3, i.cycle).bind(4, i.value).bind(5, i.repeat)
        .bind(6, mark_id);
    s.finish();
  }

  void insert_outcome(std::int64_t mark_id, const OutcomeRecord& o) override {
    SqliteStmt s(db_, "INSERT INTO outcomes(mark_id, time_utc, outcome, message, figures) "
                      "VALUES(?1, ?2, ?3, ?4, ?5)");
    s.bind(1, mark_id).bind(2, o.time_utc).bind(3, std::string(to_string(o.outcome)))
        .bind(4, o.message).bind(5, o.figures.dump());
    s.finish();
  }

  void insert_text(const std::string& text, const std::string& object, std::int64_t mark_id) override {
    SqliteStmt s(db_, "INSERT INTO marked_texts(text, object, mark_id) VALUES(?1, ?2, ?3)");
    s.bind(1, text).bind(2, object).bind(3, mark_id);
    s.finish();
  }

  void lock_data_list(const std::string&) override {}  // the transaction holds the write lock

  void insert_data_row(const std::string& key, const std::string& list, std::int64_t row,
                       std::int64_t mark_id) override {
    SqliteStmt s(db_, "INSERT INTO data_rows(row_key, list, row, mark_id) VALUES(?1, ?2, ?3, ?4)");
    s.bind(1, key).bind(2, list).bind(3, row).bind(4, mark_id);
    s.finish();
  }

  std::vector<std::int64_t> pending_marks(const std::string& station) override {
    SqliteStmt s(db_, "SELECT m.id FROM marks m LEFT JOIN outcomes o ON o.mark_id = m.id "
                      "WHERE m.station = ?1 AND o.mark_id IS NULL ORDER BY m.id");
    s.bind(1, station);
    std::vector<std::int64_t> ids;
    while (s.step()) ids.push_back(s.i64(0));
    return ids;
  }

  void commit() override {
    db_.exec("COMMIT");
    done_ = true;
  }

 private:
  bool done_ = false;
};

// A file: URI for `path` (read-only and immutable opens), its reserved characters escaped.
std::string file_uri(const std::string& path, const char* query) {
  std::string uri = "file:";
  for (unsigned char c : std::filesystem::absolute(path).string()) {
    if (c == '%' || c == '?' || c == '#' || c < 0x21 || c >= 0x7f) {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      uri += hex;
    } else {
      uri += static_cast<char>(c);
    }
  }
  return uri + "?" + query;
}

class SqliteBackend final : public StoreBackend {
 public:
  SqliteBackend(const std::string& path, StoreAccess access, const SqliteOptions& options)
      : path_(path), options_(options), read_only_(access == StoreAccess::read_only) {
    if (access != StoreAccess::create && !std::filesystem::exists(path))
      throw StoreError("serial store " + path + " does not exist (a store is created by `marker serial "
                       "create NAME` or `marker mark --job FILE --create-counters`)",
                       StoreErrorKind::missing);
    if (read_only_) {
      open_read_only();
    } else {
      const int flags = SQLITE_OPEN_READWRITE | SQLITE_OPEN_FULLMUTEX |
                        (access == StoreAccess::create ? SQLITE_OPEN_CREATE : 0);
      db_ = std::make_unique<SqliteDb>(path, flags, options.fault_injection ? sqlite_fault_vfs() : nullptr);
      wire_busy_wait();
      db_->exec("PRAGMA journal_mode=WAL");
      db_->exec("PRAGMA synchronous=FULL");
      db_->exec("PRAGMA foreign_keys=ON");
      format_ = create_or_upgrade(*db_);
    }
  }
  ~SqliteBackend() override {
    heal();
    db_.reset();     // SQLite's connection first: closing the lock descriptor drops its locks
    locks_.reset();
  }

  std::unique_ptr<StoreTransaction> begin() override {
    if (read_only_) throw StoreError("serial store " + path_ + " is open read-only");
    return std::make_unique<SqliteTransaction>(*db_, format_.version);
  }
  std::unique_ptr<StoreReader> begin_read() override {
    return std::make_unique<SqliteReader>(*db_, format_.version);
  }
  std::string describe() const override { return "sqlite:" + path_; }
  const std::string& store_id() const override { return format_.store_id; }

  bool claim_station(const std::string& station) override {
    if (read_only_) throw StoreError("serial store " + path_ + " is open read-only: no station marks through it");
    if (!locks_) locks_ = std::make_unique<StationLocks>(path_, path_);
    return locks_->claim(station);
  }

  std::vector<std::string> check(bool quick) override {
    std::vector<std::string> problems;
    {
      SqliteStmt s(*db_, quick ? "PRAGMA quick_check" : "PRAGMA integrity_check");
      while (s.step())
        if (s.text(0) != "ok") problems.push_back(s.text(0));
    }
    if (!quick) {
      SqliteStmt s(*db_, "PRAGMA foreign_key_check");
      while (s.step())
        problems.push_back("table " + s.text(0) + " row " + s.text(1) + ": refers to a missing row of " + s.text(2));
    }
    return problems;
  }

  void reconnect() override {}  // a file needs no connection
  void set_cancel(std::function<bool()> cancel) override { cancel_ = std::move(cancel); }

  void provoke(StoreStep, StoreFaultKind kind) override {
    heal();
    switch (kind) {
      case StoreFaultKind::locked:
        // A second connection holding the write lock, as another process would.
        holder_ = std::make_unique<SqliteDb>(path_, SQLITE_OPEN_READWRITE);
        holder_->exec("BEGIN IMMEDIATE");
        return;
      case StoreFaultKind::full:
      case StoreFaultKind::io:
        if (!options_.fault_injection)
          throw StoreError("serial store " + path_ + ": a disk fault needs the store opened for fault injection");
        sqlite_fail_writes(sqlite3_db_filename(db_->get(), "main"),
                           kind == StoreFaultKind::full ? SQLITE_FULL : SQLITE_IOERR_WRITE);
        return;
      case StoreFaultKind::stopped:
        throw StoreError("serial store " + path_ + ": an SQLite store has no server to stop (inject locked, full or io)");
    }
  }

  void heal() override {
    holder_.reset();
    if (options_.fault_injection) sqlite_fail_writes("", 0);
  }

 private:
  void wire_busy_wait() {
    db_->set_busy_wait(options_.busy_timeout_ms, [this] { return cancel_ && cancel_(); });
  }

  // Read-only: the store is never written, not even its schema. A WAL store needs its -shm
  // beside it; where this process can create none (a read-only folder) and no -wal is left (so
  // no writer is active), the file is opened immutable.
  void open_read_only() {
    const int flags = SQLITE_OPEN_READONLY | SQLITE_OPEN_URI | SQLITE_OPEN_FULLMUTEX;
    try {
      db_ = std::make_unique<SqliteDb>(file_uri(path_, "mode=ro"), flags, nullptr, path_);
      wire_busy_wait();
      format_ = read_format(*db_);
      return;
    } catch (const StoreError& e) {
      const auto dir = std::filesystem::absolute(path_).parent_path();
      const bool writer_possible = ::access(dir.c_str(), W_OK) == 0 || std::filesystem::exists(path_ + "-wal");
      if (e.kind() != StoreErrorKind::io || writer_possible) throw;
    }
    db_ = std::make_unique<SqliteDb>(file_uri(path_, "immutable=1"), flags, nullptr, path_);
    wire_busy_wait();
    format_ = read_format(*db_);
  }

  std::string path_;
  SqliteOptions options_;
  bool read_only_;
  std::unique_ptr<SqliteDb> db_;
  SqliteFormat format_;
  std::unique_ptr<StationLocks> locks_;
  std::unique_ptr<SqliteDb> holder_;  // provoke(locked)
  std::function<bool()> cancel_;
};

}  // namespace

std::unique_ptr<StoreBackend> open_sqlite_store(const std::string& path, StoreAccess access,
                                                const SqliteOptions& options) {
  return std::make_unique<SqliteBackend>(path, access, options);
}

}  // namespace mark
