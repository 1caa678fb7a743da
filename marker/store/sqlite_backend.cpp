#include "marker/store/sqlite_backend.hpp"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <map>

#include "marker/store/row_codec.hpp"

namespace mark {
namespace {

constexpr const char* kFormat = "marker-store/1";

// Append-only: the audit rows, the issues and the outcomes can be added, never changed.
constexpr const char* kSchema = R"SQL(
CREATE TABLE IF NOT EXISTS meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS counters(
  name TEXT PRIMARY KEY, next_value INTEGER NOT NULL, used INTEGER NOT NULL,
  period TEXT NOT NULL, cycle INTEGER NOT NULL, exhausted INTEGER NOT NULL);
CREATE TABLE IF NOT EXISTS marks(
  id INTEGER PRIMARY KEY AUTOINCREMENT, time_utc TEXT NOT NULL, station TEXT NOT NULL,
  job TEXT NOT NULL, job_sha256 TEXT NOT NULL, kind TEXT NOT NULL,
  remark_of INTEGER REFERENCES marks(id), objects TEXT NOT NULL, serials TEXT NOT NULL);
CREATE INDEX IF NOT EXISTS marks_time ON marks(time_utc);
CREATE INDEX IF NOT EXISTS marks_station ON marks(station);
CREATE TABLE IF NOT EXISTS issues(
  counter TEXT NOT NULL, period TEXT NOT NULL, cycle INTEGER NOT NULL, value INTEGER NOT NULL,
  repeat INTEGER NOT NULL, mark_id INTEGER NOT NULL REFERENCES marks(id),
  PRIMARY KEY(counter, period, cycle, value, repeat));
CREATE INDEX IF NOT EXISTS issues_mark ON issues(mark_id);
CREATE TABLE IF NOT EXISTS outcomes(
  mark_id INTEGER PRIMARY KEY REFERENCES marks(id), time_utc TEXT NOT NULL,
  outcome TEXT NOT NULL, message TEXT NOT NULL, figures TEXT NOT NULL);
CREATE TRIGGER IF NOT EXISTS marks_no_update BEFORE UPDATE ON marks
  BEGIN SELECT RAISE(ABORT, 'the audit log is append-only'); END;
CREATE TRIGGER IF NOT EXISTS marks_no_delete BEFORE DELETE ON marks
  BEGIN SELECT RAISE(ABORT, 'the audit log is append-only'); END;
CREATE TRIGGER IF NOT EXISTS issues_no_update BEFORE UPDATE ON issues
  BEGIN SELECT RAISE(ABORT, 'issued serial numbers are append-only'); END;
CREATE TRIGGER IF NOT EXISTS issues_no_delete BEFORE DELETE ON issues
  BEGIN SELECT RAISE(ABORT, 'issued serial numbers are append-only'); END;
CREATE TRIGGER IF NOT EXISTS outcomes_no_update BEFORE UPDATE ON outcomes
  BEGIN SELECT RAISE(ABORT, 'outcomes are append-only'); END;
CREATE TRIGGER IF NOT EXISTS outcomes_no_delete BEFORE DELETE ON outcomes
  BEGIN SELECT RAISE(ABORT, 'outcomes are append-only'); END;
)SQL";

class Db {
 public:
  explicit Db(std::string path) : path_(std::move(path)) {}
  ~Db() {
    if (db_) sqlite3_close_v2(db_);
  }
  sqlite3* get() const { return db_; }
  sqlite3** out() { return &db_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& what) const {
    throw StoreError("serial store " + path_ + ": " + what + ": " +
                     (db_ ? sqlite3_errmsg(db_) : "cannot open"));
  }
  void exec(const char* sql) const {
    char* err = nullptr;
    if (sqlite3_exec(db_, sql, nullptr, nullptr, &err) != SQLITE_OK) {
      const std::string msg = err ? err : "?";
      sqlite3_free(err);
      throw StoreError("serial store " + path_ + ": " + msg);
    }
  }

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
};

class Stmt {
 public:
  Stmt(const Db& db, const char* sql) : db_(db) {
    if (sqlite3_prepare_v2(db.get(), sql, -1, &s_, nullptr) != SQLITE_OK) db.fail("prepare");
  }
  ~Stmt() { sqlite3_finalize(s_); }
  Stmt& bind(int i, std::int64_t v) {
    sqlite3_bind_int64(s_, i, v);
    return *this;
  }
  Stmt& bind(int i, const std::string& v) {
    sqlite3_bind_text(s_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
    return *this;
  }
  Stmt& bind_null(int i) {
    sqlite3_bind_null(s_, i);
    return *this;
  }
  // True while there is a row.
  bool step() {
    const int rc = sqlite3_step(s_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    db_.fail("statement");
  }
  std::int64_t i64(int c) const { return sqlite3_column_int64(s_, c); }
  bool null(int c) const { return sqlite3_column_type(s_, c) == SQLITE_NULL; }
  std::string text(int c) const {
    const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(s_, c));
    return p ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(s_, c))) : std::string();
  }

 private:
  const Db& db_;
  sqlite3_stmt* s_ = nullptr;
};

constexpr const char* kAuditSelect =
    "SELECT m.id, m.time_utc, m.station, m.job, m.job_sha256, m.kind, m.remark_of, m.objects, "
    "m.serials, o.time_utc, o.outcome, o.message, o.figures FROM marks m "
    "LEFT JOIN outcomes o ON o.mark_id = m.id ";

AuditRow audit_from(const Stmt& s) {
  AuditRow r;
  r.id = s.i64(0);
  r.mark.time_utc = s.text(1);
  r.mark.station = s.text(2);
  r.mark.job = s.text(3);
  r.mark.job_sha256 = s.text(4);
  r.mark.kind = parse_audit_kind(s.text(5)).value_or(AuditKind::mark);
  if (!s.null(6)) r.mark.remark_of = s.i64(6);
  r.mark.objects = objects_from_json(s.text(7));
  r.mark.serials = serials_from_json(s.text(8));
  if (!s.null(10)) {
    OutcomeRecord o;
    o.time_utc = s.text(9);
    o.outcome = parse_outcome(s.text(10)).value_or(Outcome::failed);
    o.message = s.text(11);
    o.figures = nlohmann::json::parse(s.text(12));
    r.outcome = std::move(o);
  }
  return r;
}

class SqliteTransaction : public StoreTransaction {
 public:
  explicit SqliteTransaction(const Db& db) : db_(db) {
    // IMMEDIATE: the write lock is taken now, so two writers never both read a counter and
    // then race to update it.
    db_.exec("BEGIN IMMEDIATE");
  }
  ~SqliteTransaction() override {
    if (!done_) sqlite3_exec(db_.get(), "ROLLBACK", nullptr, nullptr, nullptr);
  }

  CounterState lock_counter(const std::string& name, const CounterState& initial) override {
    Stmt ins(db_, "INSERT OR IGNORE INTO counters(name, next_value, used, period, cycle, exhausted) "
                  "VALUES(?1, ?2, ?3, ?4, ?5, ?6)");
    ins.bind(1, name).bind(2, initial.next).bind(3, initial.used).bind(4, initial.period)
        .bind(5, initial.cycle).bind(6, std::int64_t{initial.exhausted});
    ins.step();
    Stmt q(db_, "SELECT next_value, used, period, cycle, exhausted FROM counters WHERE name = ?1");
    q.bind(1, name);
    if (!q.step()) db_.fail("counter '" + name + "' vanished");
    return state_from(q);
  }

  void update_counter(const std::string& name, const CounterState& s) override {
    Stmt u(db_, "UPDATE counters SET next_value = ?2, used = ?3, period = ?4, cycle = ?5, "
                "exhausted = ?6 WHERE name = ?1 RETURNING next_value");
    u.bind(1, name).bind(2, s.next).bind(3, s.used).bind(4, s.period).bind(5, s.cycle)
        .bind(6, std::int64_t{s.exhausted});
    if (!u.step() || u.i64(0) != s.next) db_.fail("counter '" + name + "' was not updated");
    while (u.step()) {
    }
  }

  std::int64_t insert_mark(const MarkRecord& m) override {
    Stmt s(db_, "INSERT INTO marks(time_utc, station, job, job_sha256, kind, remark_of, objects, "
                "serials) VALUES(?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8) RETURNING id");
    s.bind(1, m.time_utc).bind(2, m.station).bind(3, m.job).bind(4, m.job_sha256)
        .bind(5, std::string(to_string(m.kind)));
    if (m.remark_of)
      s.bind(6, *m.remark_of);
    else
      s.bind_null(6);
    s.bind(7, objects_to_json(m.objects)).bind(8, serials_to_json(m.serials));
    if (!s.step()) db_.fail("audit row not written");
    const std::int64_t id = s.i64(0);
    while (s.step()) {
    }
    return id;
  }

  void insert_issue(const Issue& i, std::int64_t mark_id) override {
    Stmt s(db_, "INSERT INTO issues(counter, period, cycle, value, repeat, mark_id) "
                "VALUES(?1, ?2, ?3, ?4, ?5, ?6)");
    s.bind(1, i.counter).bind(2, i.period).bind(3, i.cycle).bind(4, i.value).bind(5, i.repeat)
        .bind(6, mark_id);
    s.step();
  }

  void insert_outcome(std::int64_t mark_id, const OutcomeRecord& o) override {
    Stmt s(db_, "INSERT INTO outcomes(mark_id, time_utc, outcome, message, figures) "
                "VALUES(?1, ?2, ?3, ?4, ?5)");
    s.bind(1, mark_id).bind(2, o.time_utc).bind(3, std::string(to_string(o.outcome)))
        .bind(4, o.message).bind(5, o.figures.dump());
    s.step();
  }

  std::optional<std::pair<std::int64_t, std::int64_t>> issued_range(
      const std::string& counter, const std::string& period, std::int64_t cycle) override {
    Stmt s(db_, "SELECT MIN(value), MAX(value) FROM issues WHERE counter = ?1 AND period = ?2 "
                "AND cycle = ?3");
    s.bind(1, counter).bind(2, period).bind(3, cycle);
    if (!s.step() || s.null(0)) return std::nullopt;
    return std::make_pair(s.i64(0), s.i64(1));
  }

  std::vector<std::int64_t> pending_marks(const std::string& station) override {
    Stmt s(db_, "SELECT m.id FROM marks m LEFT JOIN outcomes o ON o.mark_id = m.id "
                "WHERE m.station = ?1 AND o.mark_id IS NULL ORDER BY m.id");
    s.bind(1, station);
    std::vector<std::int64_t> ids;
    while (s.step()) ids.push_back(s.i64(0));
    return ids;
  }

  std::vector<AuditRow> audit(const std::string& since) override {
    Stmt s(db_, (std::string(kAuditSelect) + "WHERE m.time_utc >= ?1 ORDER BY m.id").c_str());
    s.bind(1, since);
    std::vector<AuditRow> rows;
    while (s.step()) rows.push_back(audit_from(s));
    return rows;
  }

  std::optional<AuditRow> audit_row(std::int64_t id) override {
    Stmt s(db_, (std::string(kAuditSelect) + "WHERE m.id = ?1").c_str());
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return audit_from(s);
  }

  std::vector<std::pair<std::string, CounterState>> counters() override {
    Stmt s(db_, "SELECT next_value, used, period, cycle, exhausted, name FROM counters ORDER BY name");
    std::vector<std::pair<std::string, CounterState>> out;
    while (s.step()) out.emplace_back(s.text(5), state_from(s));
    return out;
  }

  std::vector<std::pair<Issue, std::int64_t>> issues(const std::string& counter) override {
    Stmt s(db_, "SELECT period, cycle, value, repeat, mark_id FROM issues WHERE counter = ?1 "
                "ORDER BY mark_id, value");
    s.bind(1, counter);
    std::vector<std::pair<Issue, std::int64_t>> out;
    while (s.step())
      out.push_back({Issue{counter, s.i64(2), s.i64(3), s.text(0), s.i64(1)}, s.i64(4)});
    return out;
  }

  void commit() override {
    db_.exec("COMMIT");
    done_ = true;
  }

 private:
  static CounterState state_from(const Stmt& q) {
    CounterState s;
    s.next = q.i64(0);
    s.used = q.i64(1);
    s.period = q.text(2);
    s.cycle = q.i64(3);
    s.exhausted = q.i64(4) != 0;
    return s;
  }

  const Db& db_;
  bool done_ = false;
};

class SqliteBackend : public StoreBackend {
 public:
  SqliteBackend(const std::string& path, StoreAccess access) : db_(path) {
    if (access == StoreAccess::existing && !std::filesystem::exists(path))
      throw StoreError("serial store " + path + " does not exist (a job's store is created by "
                       "its first mark; name another with --store)");
    const int flags = SQLITE_OPEN_READWRITE | SQLITE_OPEN_FULLMUTEX |
                      (access == StoreAccess::create ? SQLITE_OPEN_CREATE : 0);
    if (sqlite3_open_v2(path.c_str(), db_.out(), flags, nullptr) != SQLITE_OK) db_.fail("open");
    sqlite3_extended_result_codes(db_.get(), 1);
    sqlite3_busy_timeout(db_.get(), 30000);
    db_.exec("PRAGMA journal_mode=WAL");
    db_.exec("PRAGMA synchronous=FULL");
    db_.exec("PRAGMA foreign_keys=ON");
    db_.exec("BEGIN IMMEDIATE");
    try {
      db_.exec(kSchema);
      Stmt get(db_, "SELECT value FROM meta WHERE key = 'format'");
      if (get.step()) {
        if (get.text(0) != kFormat)
          throw StoreError("serial store " + path + " has format '" + get.text(0) +
                           "', this program reads " + kFormat);
      } else {
        Stmt put(db_, "INSERT INTO meta(key, value) VALUES('format', ?1)");
        put.bind(1, std::string(kFormat));
        put.step();
      }
      db_.exec("COMMIT");
    } catch (...) {
      sqlite3_exec(db_.get(), "ROLLBACK", nullptr, nullptr, nullptr);
      throw;
    }
  }
  ~SqliteBackend() override {
    for (auto& [name, fd] : station_locks_) close(fd);
  }

  std::unique_ptr<StoreTransaction> begin() override {
    return std::make_unique<SqliteTransaction>(db_);
  }
  std::string describe() const override { return "sqlite:" + db_.path(); }

  bool claim_station(const std::string& station) override {
    if (station_locks_.count(station)) return true;
    // A lock file beside the store per station; the kernel drops the lock when the process
    // dies, however it dies.
    std::string safe;
    for (unsigned char c : station) {
      if (std::isalnum(c) || c == '-' || c == '_') {
        safe += static_cast<char>(c);
      } else {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%%%02X", c);
        safe += hex;
      }
    }
    const std::string lock = db_.path() + ".station-" + safe + ".lock";
    const int fd = open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw StoreError("serial store " + db_.path() + ": cannot open " + lock);
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      close(fd);
      return false;
    }
    station_locks_[station] = fd;
    return true;
  }

 private:
  Db db_;
  std::map<std::string, int> station_locks_;
};

}  // namespace

std::unique_ptr<StoreBackend> open_sqlite_store(const std::string& path, StoreAccess access) {
  return std::make_unique<SqliteBackend>(path, access);
}

}  // namespace mark
