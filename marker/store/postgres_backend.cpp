#include "marker/store/postgres_backend.hpp"

#include <libpq-fe.h>

#include <array>
#include <cstring>

#include "marker/store/row_codec.hpp"

namespace mark {
namespace {

constexpr const char* kFormat = "marker-store/1";

constexpr const char* kSchema = R"SQL(
CREATE TABLE IF NOT EXISTS meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS counters(
  name TEXT PRIMARY KEY, next_value BIGINT NOT NULL, used BIGINT NOT NULL,
  period TEXT NOT NULL, cycle BIGINT NOT NULL, exhausted BOOLEAN NOT NULL);
CREATE TABLE IF NOT EXISTS marks(
  id BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY, time_utc TEXT NOT NULL,
  station TEXT NOT NULL, job TEXT NOT NULL, job_sha256 TEXT NOT NULL, kind TEXT NOT NULL,
  remark_of BIGINT REFERENCES marks(id), objects TEXT NOT NULL, serials TEXT NOT NULL);
CREATE INDEX IF NOT EXISTS marks_time ON marks(time_utc);
CREATE INDEX IF NOT EXISTS marks_station ON marks(station);
CREATE TABLE IF NOT EXISTS issues(
  counter TEXT NOT NULL, period TEXT NOT NULL, cycle BIGINT NOT NULL, value BIGINT NOT NULL,
  repeat BIGINT NOT NULL, mark_id BIGINT NOT NULL REFERENCES marks(id),
  PRIMARY KEY(counter, period, cycle, value, repeat));
CREATE INDEX IF NOT EXISTS issues_mark ON issues(mark_id);
CREATE TABLE IF NOT EXISTS outcomes(
  mark_id BIGINT PRIMARY KEY REFERENCES marks(id), time_utc TEXT NOT NULL,
  outcome TEXT NOT NULL, message TEXT NOT NULL, figures TEXT NOT NULL);
CREATE OR REPLACE FUNCTION marker_append_only() RETURNS trigger LANGUAGE plpgsql AS $$
  BEGIN RAISE EXCEPTION 'table % is append-only', TG_TABLE_NAME; END $$;
CREATE OR REPLACE TRIGGER marks_append_only BEFORE UPDATE OR DELETE ON marks
  FOR EACH ROW EXECUTE FUNCTION marker_append_only();
CREATE OR REPLACE TRIGGER marks_no_truncate BEFORE TRUNCATE ON marks
  FOR EACH STATEMENT EXECUTE FUNCTION marker_append_only();
CREATE OR REPLACE TRIGGER issues_append_only BEFORE UPDATE OR DELETE ON issues
  FOR EACH ROW EXECUTE FUNCTION marker_append_only();
CREATE OR REPLACE TRIGGER issues_no_truncate BEFORE TRUNCATE ON issues
  FOR EACH STATEMENT EXECUTE FUNCTION marker_append_only();
CREATE OR REPLACE TRIGGER outcomes_append_only BEFORE UPDATE OR DELETE ON outcomes
  FOR EACH ROW EXECUTE FUNCTION marker_append_only();
CREATE OR REPLACE TRIGGER outcomes_no_truncate BEFORE TRUNCATE ON outcomes
  FOR EACH STATEMENT EXECUTE FUNCTION marker_append_only();
)SQL";

class Result {
 public:
  explicit Result(PGresult* r) : r_(r) {}
  ~Result() { PQclear(r_); }
  Result(const Result&) = delete;
  int rows() const { return PQntuples(r_); }
  bool null(int row, int c) const { return PQgetisnull(r_, row, c); }
  std::string text(int row, int c) const { return PQgetvalue(r_, row, c); }
  std::int64_t i64(int row, int c) const { return std::stoll(PQgetvalue(r_, row, c)); }

 private:
  PGresult* r_;
};

class Conn {
 public:
  explicit Conn(const std::string& url) : c_(PQconnectdb(url.c_str())) {
    if (PQstatus(c_) != CONNECTION_OK) {
      const std::string msg = PQerrorMessage(c_);
      PQfinish(c_);
      c_ = nullptr;
      throw StoreError("serial store " + redacted(url) + ": cannot connect: " + first_line(msg));
    }
    std::string host = PQhost(c_) ? PQhost(c_) : "";
    describe_ = "postgresql://" + std::string(PQuser(c_)) + "@" + host + ":" + PQport(c_) + "/" +
                PQdb(c_);
  }
  ~Conn() {
    if (c_) PQfinish(c_);
  }
  const std::string& describe() const { return describe_; }

  // Runs `sql` with text parameters; throws StoreError unless it returned rows or completed.
  Result run(const char* sql, std::initializer_list<std::optional<std::string>> params = {}) const {
    std::array<const char*, 16> values{};
    std::size_t n = 0;
    for (const auto& p : params) values[n++] = p ? p->c_str() : nullptr;
    PGresult* r = n == 0 ? PQexec(c_, sql)
                         : PQexecParams(c_, sql, static_cast<int>(n), nullptr, values.data(),
                                        nullptr, nullptr, 0);
    const ExecStatusType st = PQresultStatus(r);
    if (st != PGRES_COMMAND_OK && st != PGRES_TUPLES_OK) {
      const std::string msg = PQresultErrorMessage(r);
      PQclear(r);
      throw StoreError("serial store " + describe_ + ": " + first_line(msg));
    }
    return Result(r);
  }

 private:
  static std::string first_line(const std::string& s) {
    const std::size_t nl = s.find('\n');
    return nl == std::string::npos ? s : s.substr(0, nl);
  }
  // The URL without a password, for messages.
  static std::string redacted(const std::string& url) {
    const std::size_t scheme = url.find("://");
    const std::size_t at = url.find('@');
    if (scheme == std::string::npos || at == std::string::npos) return url;
    const std::size_t colon = url.find(':', scheme + 3);
    if (colon == std::string::npos || colon > at) return url;
    return url.substr(0, colon) + ":***" + url.substr(at);
  }

  PGconn* c_;
  std::string describe_;
};

std::string num(std::int64_t v) { return std::to_string(v); }

constexpr const char* kAuditSelect =
    "SELECT m.id, m.time_utc, m.station, m.job, m.job_sha256, m.kind, m.remark_of, m.objects, "
    "m.serials, o.time_utc, o.outcome, o.message, o.figures FROM marks m "
    "LEFT JOIN outcomes o ON o.mark_id = m.id ";

AuditRow audit_from(const Result& r, int i) {
  AuditRow a;
  a.id = r.i64(i, 0);
  a.mark.time_utc = r.text(i, 1);
  a.mark.station = r.text(i, 2);
  a.mark.job = r.text(i, 3);
  a.mark.job_sha256 = r.text(i, 4);
  a.mark.kind = parse_audit_kind(r.text(i, 5)).value_or(AuditKind::mark);
  if (!r.null(i, 6)) a.mark.remark_of = r.i64(i, 6);
  a.mark.objects = objects_from_json(r.text(i, 7));
  a.mark.serials = serials_from_json(r.text(i, 8));
  if (!r.null(i, 10)) {
    OutcomeRecord o;
    o.time_utc = r.text(i, 9);
    o.outcome = parse_outcome(r.text(i, 10)).value_or(Outcome::failed);
    o.message = r.text(i, 11);
    o.figures = nlohmann::json::parse(r.text(i, 12));
    a.outcome = std::move(o);
  }
  return a;
}

CounterState state_from(const Result& r, int i) {
  CounterState s;
  s.next = r.i64(i, 0);
  s.used = r.i64(i, 1);
  s.period = r.text(i, 2);
  s.cycle = r.i64(i, 3);
  s.exhausted = r.text(i, 4) == "t";
  return s;
}

class PgTransaction : public StoreTransaction {
 public:
  explicit PgTransaction(const Conn& c) : c_(c) { c_.run("BEGIN"); }
  ~PgTransaction() override {
    if (!done_) {
      try {
        c_.run("ROLLBACK");
      } catch (...) {
      }
    }
  }

  CounterState lock_counter(const std::string& name, const CounterState& init) override {
    c_.run("INSERT INTO counters(name, next_value, used, period, cycle, exhausted) "
           "VALUES($1, $2, $3, $4, $5, $6) ON CONFLICT (name) DO NOTHING",
           {name, num(init.next), num(init.used), init.period, num(init.cycle),
            std::string(init.exhausted ? "true" : "false")});
    const Result r = c_.run("SELECT next_value, used, period, cycle, exhausted FROM counters "
                            "WHERE name = $1 FOR UPDATE",
                            {name});
    if (r.rows() != 1) throw StoreError("serial store " + c_.describe() + ": counter '" + name + "' vanished");
    return state_from(r, 0);
  }

  void update_counter(const std::string& name, const CounterState& s) override {
    const Result r = c_.run("UPDATE counters SET next_value = $2, used = $3, period = $4, "
                            "cycle = $5, exhausted = $6 WHERE name = $1 RETURNING next_value",
                            {name, num(s.next), num(s.used), s.period, num(s.cycle),
                             std::string(s.exhausted ? "true" : "false")});
    if (r.rows() != 1 || r.i64(0, 0) != s.next)
      throw StoreError("serial store " + c_.describe() + ": counter '" + name + "' was not updated");
  }

  std::int64_t insert_mark(const MarkRecord& m) override {
    const Result r = c_.run(
        "INSERT INTO marks(time_utc, station, job, job_sha256, kind, remark_of, objects, serials) "
        "VALUES($1, $2, $3, $4, $5, $6, $7, $8) RETURNING id",
        {m.time_utc, m.station, m.job, m.job_sha256, std::string(to_string(m.kind)),
         m.remark_of ? std::optional<std::string>(num(*m.remark_of)) : std::nullopt,
         objects_to_json(m.objects), serials_to_json(m.serials)});
    return r.i64(0, 0);
  }

  void insert_issue(const Issue& i, std::int64_t mark_id) override {
    c_.run("INSERT INTO issues(counter, period, cycle, value, repeat, mark_id) "
           "VALUES($1, $2, $3, $4, $5, $6)",
           {i.counter, i.period, num(i.cycle), num(i.value), num(i.repeat), num(mark_id)});
  }

  void insert_outcome(std::int64_t mark_id, const OutcomeRecord& o) override {
    c_.run("INSERT INTO outcomes(mark_id, time_utc, outcome, message, figures) "
           "VALUES($1, $2, $3, $4, $5)",
           {num(mark_id), o.time_utc, std::string(to_string(o.outcome)), o.message,
            o.figures.dump()});
  }

  std::optional<std::pair<std::int64_t, std::int64_t>> issued_range(
      const std::string& counter, const std::string& period, std::int64_t cycle) override {
    const Result r = c_.run("SELECT MIN(value), MAX(value) FROM issues WHERE counter = $1 AND "
                            "period = $2 AND cycle = $3",
                            {counter, period, num(cycle)});
    if (r.rows() != 1 || r.null(0, 0)) return std::nullopt;
    return std::make_pair(r.i64(0, 0), r.i64(0, 1));
  }

  std::vector<std::int64_t> pending_marks(const std::string& station) override {
    const Result r = c_.run("SELECT m.id FROM marks m LEFT JOIN outcomes o ON o.mark_id = m.id "
                            "WHERE m.station = $1 AND o.mark_id IS NULL ORDER BY m.id",
                            {station});
    std::vector<std::int64_t> ids;
    for (int i = 0; i < r.rows(); ++i) ids.push_back(r.i64(i, 0));
    return ids;
  }

  std::vector<AuditRow> audit(const std::string& since) override {
    const Result r =
        c_.run((std::string(kAuditSelect) + "WHERE m.time_utc >= $1 ORDER BY m.id").c_str(), {since});
    std::vector<AuditRow> rows;
    for (int i = 0; i < r.rows(); ++i) rows.push_back(audit_from(r, i));
    return rows;
  }

  std::optional<AuditRow> audit_row(std::int64_t id) override {
    const Result r = c_.run((std::string(kAuditSelect) + "WHERE m.id = $1").c_str(), {num(id)});
    if (r.rows() != 1) return std::nullopt;
    return audit_from(r, 0);
  }

  std::vector<std::pair<std::string, CounterState>> counters() override {
    const Result r = c_.run("SELECT next_value, used, period, cycle, exhausted, name FROM counters "
                            "ORDER BY name");
    std::vector<std::pair<std::string, CounterState>> out;
    for (int i = 0; i < r.rows(); ++i) out.emplace_back(r.text(i, 5), state_from(r, i));
    return out;
  }

  std::vector<std::pair<Issue, std::int64_t>> issues(const std::string& counter) override {
    const Result r = c_.run("SELECT period, cycle, value, repeat, mark_id FROM issues WHERE "
                            "counter = $1 ORDER BY mark_id, value",
                            {counter});
    std::vector<std::pair<Issue, std::int64_t>> out;
    for (int i = 0; i < r.rows(); ++i)
      out.push_back({Issue{counter, r.i64(i, 2), r.i64(i, 3), r.text(i, 0), r.i64(i, 1)}, r.i64(i, 4)});
    return out;
  }

  void commit() override {
    c_.run("COMMIT");
    done_ = true;
  }

 private:
  const Conn& c_;
  bool done_ = false;
};

class PgBackend : public StoreBackend {
 public:
  explicit PgBackend(const std::string& url) : c_(url) {
    c_.run("SET client_min_messages = warning");
    // Stations starting together must not race to create the tables: one at a time.
    c_.run("BEGIN");
    try {
      c_.run("SELECT pg_advisory_xact_lock(7403, 1)");
      c_.run(kSchema);
      const Result f = c_.run("SELECT value FROM meta WHERE key = 'format'");
      if (f.rows() == 0)
        c_.run("INSERT INTO meta(key, value) VALUES('format', $1)", {std::string(kFormat)});
      else if (f.text(0, 0) != kFormat)
        throw StoreError("serial store " + c_.describe() + " has format '" + f.text(0, 0) +
                         "', this program reads " + kFormat);
      c_.run("COMMIT");
    } catch (...) {
      try {
        c_.run("ROLLBACK");
      } catch (...) {
      }
      throw;
    }
  }

  std::unique_ptr<StoreTransaction> begin() override { return std::make_unique<PgTransaction>(c_); }
  std::string describe() const override { return c_.describe(); }

  bool claim_station(const std::string& station) override {
    // A session-level advisory lock: the server drops it when this connection ends, however
    // the station's process ends.
    const Result r = c_.run("SELECT pg_try_advisory_lock(7403, hashtext($1))", {station});
    return r.text(0, 0) == "t";
  }

 private:
  Conn c_;
};

}  // namespace

std::unique_ptr<StoreBackend> open_postgres_store(const std::string& url) {
  return std::make_unique<PgBackend>(url);
}

}  // namespace mark
