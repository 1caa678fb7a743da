#include "marker/store/postgres_backend.hpp"

#include <random>
#include <set>

#include "marker/store/pg_conn.hpp"
#include "marker/store/store_format.hpp"
#include "marker/store/row_codec.hpp"

namespace mark {
namespace {


constexpr const char* kPgTables1 = R"SQL(
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

// Version 2 (see sqlite_schema.cpp for what each part is for).
constexpr const char* kPgTables2 = R"SQL(
ALTER TABLE marks ADD COLUMN IF NOT EXISTS reason TEXT NOT NULL DEFAULT '';
ALTER TABLE marks ADD COLUMN IF NOT EXISTS note TEXT NOT NULL DEFAULT '';
ALTER TABLE marks ADD COLUMN IF NOT EXISTS data_list TEXT;
ALTER TABLE marks ADD COLUMN IF NOT EXISTS data_row BIGINT;
CREATE TABLE IF NOT EXISTS marked_texts(
  text TEXT PRIMARY KEY, object TEXT NOT NULL, mark_id BIGINT NOT NULL REFERENCES marks(id));
CREATE TABLE IF NOT EXISTS data_rows(
  row_key TEXT PRIMARY KEY, list TEXT NOT NULL, row BIGINT NOT NULL,
  mark_id BIGINT NOT NULL REFERENCES marks(id));
CREATE INDEX IF NOT EXISTS issues_value ON issues(value);
CREATE INDEX IF NOT EXISTS marks_remark ON marks(remark_of);
CREATE INDEX IF NOT EXISTS marked_texts_mark ON marked_texts(mark_id);
CREATE OR REPLACE TRIGGER marked_texts_append_only BEFORE UPDATE OR DELETE ON marked_texts
  FOR EACH ROW EXECUTE FUNCTION marker_append_only();
CREATE OR REPLACE TRIGGER marked_texts_no_truncate BEFORE TRUNCATE ON marked_texts
  FOR EACH STATEMENT EXECUTE FUNCTION marker_append_only();
CREATE OR REPLACE TRIGGER data_rows_append_only BEFORE UPDATE OR DELETE ON data_rows
  FOR EACH ROW EXECUTE FUNCTION marker_append_only();
CREATE OR REPLACE TRIGGER data_rows_no_truncate BEFORE TRUNCATE ON data_rows
  FOR EACH STATEMENT EXECUTE FUNCTION marker_append_only();
)SQL";

constexpr const char* kPgBackfill2 = R"SQL(
INSERT INTO marked_texts(text, object, mark_id)
  SELECT o->>'text', o->>'name', m.id FROM marks m, json_array_elements(m.objects::json) o
  WHERE m.kind = 'mark' AND m.serials <> '{}' ORDER BY m.id ON CONFLICT DO NOTHING
)SQL";

using Params = std::vector<std::optional<std::string>>;

std::string num(std::int64_t v) { return std::to_string(v); }

std::string pg_audit_select(int version) {
  return std::string("SELECT m.id, m.time_utc, m.station, m.job, m.job_sha256, m.kind, m.remark_of, "
                     "m.objects, m.serials, ") +
         (version >= 2 ? "m.reason, m.note, m.data_list, m.data_row, " : "'', '', NULL, NULL, ") +
         "o.time_utc, o.outcome, o.message, o.figures, "
         "(SELECT json_agg(json_build_array(i.counter, i.period, i.cycle, i.value, i.repeat)) "
         "FROM issues i WHERE i.mark_id = COALESCE(m.remark_of, m.id)) "
         "FROM marks m LEFT JOIN outcomes o ON o.mark_id = m.id ";
}

// The query and its parameters, numbered in order of use (PostgreSQL types every parameter,
// so none may go unused).
std::pair<std::string, Params> pg_audit_query(const AuditFilter& f, int version) {
  Params params;
  const auto param = [&](std::string v) {
    params.push_back(std::move(v));
    std::string p = "$";
    return p.append(std::to_string(params.size()));
  };
  std::string where;
  const auto add = [&](const std::string& cond) { where += (where.empty() ? "WHERE " : " AND ") + cond; };
  if (!f.since_utc.empty()) add("m.time_utc >= " + param(f.since_utc));
  if (f.value) {
    std::string issued = "SELECT mark_id FROM issues WHERE value = " + param(num(*f.value)) + "::bigint";
    if (!f.counter.empty()) issued += " AND counter = " + param(f.counter);
    add("(m.id IN (" + issued + ") OR m.remark_of IN (" + issued + "))");
  }
  if (f.text) {
    const std::string t = param(*f.text);
    if (version >= 2)
      add("(m.id IN (SELECT mark_id FROM marked_texts WHERE text = " + t +
          ") OR m.remark_of IN (SELECT mark_id FROM marked_texts WHERE text = " + t + "))");
    else
      add("EXISTS (SELECT 1 FROM json_array_elements(m.objects::json) j WHERE j->>'text' = " + t + ")");
  }
  if (!f.job.empty()) add("m.job = " + param(f.job));
  std::string sql = pg_audit_select(version) + where;
  if (f.limit)
    sql = "SELECT * FROM (" + sql + " ORDER BY m.id DESC LIMIT " + param(num(*f.limit)) + "::bigint) recent ORDER BY 1";
  else
    sql += " ORDER BY m.id";
  return {sql, params};
}

AuditRow decode(const PgResult& r, int row, const std::string& store) {
  return audit_row_from(
      [&](int c) -> std::optional<std::string> {
        if (r.null(row, c)) return std::nullopt;
        return r.text(row, c);
      },
      store);
}

CounterState state_from(const PgResult& r, int i, int first) {
  CounterState s;
  s.next = r.i64(i, first);
  s.used = r.i64(i, first + 1);
  s.period = r.text(i, first + 2);
  s.cycle = r.i64(i, first + 3);
  s.exhausted = r.text(i, first + 4) == "t";
  return s;
}

std::optional<std::int64_t> one(const PgResult& r) {
  if (r.rows() < 1) return std::nullopt;
  return r.i64(0, 0);
}

template <class Base>
class PgReading : public Base {
 public:
  PgReading(PgConn& c, int version) : c_(c), version_(version) {}

  void audit(const AuditFilter& f, const std::function<bool(const AuditRow&)>& row) override {
    const auto [sql, params] = pg_audit_query(f, version_);
    c_.stream(sql, params, [&](const PgResult& r) { return row(decode(r, 0, c_.describe())); });
  }

  std::optional<AuditRow> audit_row(std::int64_t id) override {
    const PgResult r = c_.run(pg_audit_select(version_) + "WHERE m.id = $1", {num(id)});
    if (r.rows() != 1) return std::nullopt;
    return decode(r, 0, c_.describe());
  }

  std::optional<CounterState> counter(const std::string& name) override {
    const PgResult r = c_.run("SELECT next_value, used, period, cycle, exhausted FROM counters WHERE name = $1", {name});
    if (r.rows() != 1) return std::nullopt;
    return state_from(r, 0, 0);
  }

  std::vector<std::pair<std::string, CounterState>> counters() override {
    const PgResult r = c_.run("SELECT name, next_value, used, period, cycle, exhausted FROM counters ORDER BY name");
    std::vector<std::pair<std::string, CounterState>> out;
    for (int i = 0; i < r.rows(); ++i) out.emplace_back(r.text(i, 0), state_from(r, i, 1));
    return out;
  }

  void issues(const std::string& counter,
              const std::function<void(const Issue&, std::int64_t)>& each) override {
    c_.stream("SELECT period, cycle, value, repeat, mark_id FROM issues WHERE counter = $1 ORDER BY mark_id, value",
              {counter}, [&](const PgResult& r) {
                each(Issue{counter, r.i64(0, 2), r.i64(0, 3), r.text(0, 0), r.i64(0, 1)}, r.i64(0, 4));
                return true;
              });
  }

  std::optional<std::pair<std::int64_t, std::int64_t>> issued_range(
      const std::string& counter, const std::string& period, std::int64_t cycle) override {
    const PgResult r = c_.run("SELECT MIN(value), MAX(value) FROM issues WHERE counter = $1 AND period = $2 AND cycle = $3",
                              {counter, period, num(cycle)});
    if (r.rows() != 1 || r.null(0, 0)) return std::nullopt;
    return std::make_pair(r.i64(0, 0), r.i64(0, 1));
  }

  std::optional<std::int64_t> issue_owner(const Issue& i) override {
    return one(c_.run("SELECT mark_id FROM issues WHERE counter = $1 AND period = $2 AND cycle = $3 AND "
                      "value = $4 AND repeat = $5",
                      {i.counter, i.period, num(i.cycle), num(i.value), num(i.repeat)}));
  }

  std::optional<std::int64_t> text_owner(const std::string& text) override {
    if (version_ < 2) return std::nullopt;
    return one(c_.run("SELECT mark_id FROM marked_texts WHERE text = $1", {text}));
  }

  std::optional<std::int64_t> data_row_owner(const std::string& key) override {
    if (version_ < 2) return std::nullopt;
    return one(c_.run("SELECT mark_id FROM data_rows WHERE row_key = $1", {key}));
  }

  std::vector<RemarkRow> remarks_of(std::int64_t original) override {
    const PgResult r = c_.run("SELECT m.id, o.outcome FROM marks m LEFT JOIN outcomes o ON o.mark_id = m.id "
                              "WHERE m.remark_of = $1 AND m.kind = 'remark' ORDER BY m.id",
                              {num(original)});
    std::vector<RemarkRow> out;
    for (int i = 0; i < r.rows(); ++i) {
      RemarkRow row{r.i64(i, 0), std::nullopt};
      if (!r.null(i, 1)) row.outcome = parse_outcome(r.text(i, 1));
      out.push_back(row);
    }
    return out;
  }

 protected:
  PgConn& c_;
  int version_;
};

// A snapshot of the store that takes no lock a writer waits for (MVCC); no statement timeout,
// so reading a large log to its end is not cut off.
class PgReader final : public PgReading<StoreReader> {
 public:
  PgReader(PgConn& c, int version) : PgReading(c, version) {
    c_.run("BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY; SET LOCAL statement_timeout = 0");
  }
  ~PgReader() override {
    try {
      if (!c_.broken()) c_.run("ROLLBACK");
    } catch (...) {
    }
  }
};

class PgTransaction final : public PgReading<StoreTransaction> {
 public:
  PgTransaction(PgConn& c, int version) : PgReading(c, version) { c_.run("BEGIN"); }
  ~PgTransaction() override {
    if (done_) return;
    try {
      if (!c_.broken()) c_.run("ROLLBACK");
    } catch (...) {
    }
  }

  std::optional<CounterState> lock_counter(const std::string& name) override {
    const PgResult r = c_.run("SELECT next_value, used, period, cycle, exhausted FROM counters WHERE name = $1 FOR UPDATE",
                              {name});
    if (r.rows() != 1) return std::nullopt;
    return state_from(r, 0, 0);
  }

  void create_counter(const std::string& name, const CounterState& s) override {
    c_.run("INSERT INTO counters(name, next_value, used, period, cycle, exhausted) VALUES($1, $2, $3, $4, $5, $6)",
           {name, num(s.next), num(s.used), s.period, num(s.cycle), std::string(s.exhausted ? "true" : "false")});
  }

  void update_counter(const std::string& name, const CounterState& s) override {
    const PgResult r = c_.run("UPDATE counters SET next_value = $2, used = $3, period = $4, cycle = $5, "
                              "exhausted = $6 WHERE name = $1 RETURNING next_value",
                              {name, num(s.next), num(s.used), s.period, num(s.cycle),
                               std::string(s.exhausted ? "true" : "false")});
    if (r.rows() != 1 || r.i64(0, 0) != s.next)
      throw StoreError("serial store " + c_.describe() + ": counter '" + name + "' was not updated");
  }

  std::int64_t insert_mark(const MarkRecord& m) override {
    const PgResult r = c_.run(
        "INSERT INTO marks(time_utc, station, job, job_sha256, kind, remark_of, objects, serials, reason, "
        "note, data_list, data_row) VALUES($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12) RETURNING id",
        {m.time_utc, m.station, m.job, m.job_sha256, std::string(to_string(m.kind)),
         m.remark_of ? std::optional<std::string>(num(*m.remark_of)) : std::nullopt,
         objects_to_json(m.objects), serials_to_json(m.serials), m.reason, m.note,
         m.data_list.empty() ? std::nullopt : std::optional<std::string>(m.data_list),
         m.data_row ? std::optional<std::string>(num(*m.data_row)) : std::nullopt});
    return r.i64(0, 0);
  }

  void insert_issue(const Issue& i, std::int64_t mark_id) override {
    c_.run("INSERT INTO issues(counter, period, cycle, value, repeat, mark_id) VALUES($1, $2, $3, $4, $5, $6)",
           {i.counter, i.period, num(i.cycle), num(i.value), num(i.repeat), num(mark_id)});
  }

  void insert_outcome(std::int64_t mark_id, const OutcomeRecord& o) override {
    c_.run("INSERT INTO outcomes(mark_id, time_utc, outcome, message, figures) VALUES($1, $2, $3, $4, $5)",
           {num(mark_id), o.time_utc, std::string(to_string(o.outcome)), o.message, o.figures.dump()});
  }

  void insert_text(const std::string& text, const std::string& object, std::int64_t mark_id) override {
    c_.run("INSERT INTO marked_texts(text, object, mark_id) VALUES($1, $2, $3)", {text, object, num(mark_id)});
  }

  void lock_data_list(const std::string& list_key) override {
    c_.run("SELECT pg_advisory_xact_lock(7404, hashtext($1))", {list_key});
  }

  void insert_data_row(const std::string& key, const std::string& list, std::int64_t row,
                       std::int64_t mark_id) override {
    c_.run("INSERT INTO data_rows(row_key, list, row, mark_id) VALUES($1, $2, $3, $4)",
           {key, list, num(row), num(mark_id)});
  }

  std::vector<std::int64_t> pending_marks(const std::string& station) override {
    const PgResult r = c_.run("SELECT m.id FROM marks m LEFT JOIN outcomes o ON o.mark_id = m.id "
                              "WHERE m.station = $1 AND o.mark_id IS NULL ORDER BY m.id",
                              {station});
    std::vector<std::int64_t> ids;
    for (int i = 0; i < r.rows(); ++i) ids.push_back(r.i64(i, 0));
    return ids;
  }

  void commit() override {
    c_.run("COMMIT");
    done_ = true;
  }

 private:
  bool done_ = false;
};

std::string pg_new_store_id() {
  std::random_device rd;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string id;
  for (int i = 0; i < 32; ++i) id += kHex[rd() & 15];
  return id;
}

class PgBackend final : public StoreBackend {
 public:
  PgBackend(const std::string& url, StoreAccess access, const PgOptions& options)
      : url_(url), options_(options), conn_(std::make_unique<PgConn>(url, options)) {
    if (access == StoreAccess::read_only) read_format();
    else create_or_upgrade();
  }
  ~PgBackend() override { heal(); }

  std::unique_ptr<StoreTransaction> begin() override { return std::make_unique<PgTransaction>(*conn_, version_); }
  std::unique_ptr<StoreReader> begin_read() override { return std::make_unique<PgReader>(*conn_, version_); }
  std::string describe() const override { return conn_->describe(); }
  const std::string& store_id() const override { return store_id_; }

  bool claim_station(const std::string& station) override {
    // A session-level advisory lock: the server drops it when this connection ends, however
    // the station's process ends.
    const PgResult r = conn_->run("SELECT pg_try_advisory_lock(7403, hashtext($1))", {station});
    if (r.text(0, 0) != "t") return false;
    claimed_.insert(station);
    return true;
  }

  std::vector<std::string> check(bool) override { return {}; }  // the server checks its pages

  void reconnect() override {
    conn_->reset();
    for (const std::string& station : claimed_) {
      const PgResult r = conn_->run("SELECT pg_try_advisory_lock(7403, hashtext($1))", {station});
      if (r.text(0, 0) != "t")
        throw StoreError("serial store " + describe() + ": station '" + station +
                         "' was taken by another process while the connection was down");
    }
  }

  void set_cancel(std::function<bool()> cancel) override { conn_->set_cancel(std::move(cancel)); }

  void provoke(StoreStep step, StoreFaultKind kind) override {
    heal();
    switch (kind) {
      case StoreFaultKind::locked:
        // Another session holding the table the step writes (its rows for an allocation).
        holder_ = std::make_unique<PgConn>(url_, options_);
        holder_->run(std::string("BEGIN; LOCK TABLE ") + (step == StoreStep::allocate ? "counters" : "outcomes") +
                     " IN EXCLUSIVE MODE");
        return;
      case StoreFaultKind::stopped: {
        // The server ends this station's session, as a server restart does.
        PgConn killer(url_, options_);
        killer.run("SELECT pg_terminate_backend($1)", {std::to_string(conn_->backend_pid())});
        return;
      }
      case StoreFaultKind::full:
      case StoreFaultKind::io:
        throw StoreError("serial store " + describe() + ": a disk fault cannot be injected into a "
                         "PostgreSQL server (inject locked or stopped)");
    }
  }

  void heal() override { holder_.reset(); }

 private:
  std::string format() {
    const PgResult t = conn_->run("SELECT to_regclass('meta') IS NOT NULL");
    if (t.text(0, 0) != "t") return "";
    const PgResult f = conn_->run("SELECT value FROM meta WHERE key = 'format'");
    return f.rows() ? f.text(0, 0) : "";
  }
  int version_of(const std::string& f) { return store_format_version(describe(), f); }
  void read_store_id() {
    const PgResult id = conn_->run("SELECT value FROM meta WHERE key = 'store_id'");
    store_id_ = id.rows() ? id.text(0, 0) : "";
  }

  void read_format() {
    const std::string f = format();
    if (f.empty()) throw StoreError("serial store " + describe() + " holds no serial store", StoreErrorKind::missing);
    version_ = version_of(f);
    read_store_id();
  }

  // Only a store that is not at version 2 yet takes the schema lock and DDL: a station's start
  // must not wait behind a reader of a large log for an ALTER TABLE's exclusive lock.
  void create_or_upgrade() {
    const std::string f = format();
    if (!f.empty() && version_of(f) == 2) {
      version_ = 2;
      read_store_id();
      return;
    }
    conn_->run("BEGIN");
    try {
      // Stations starting together must not race to create the tables: one at a time.
      conn_->run("SET LOCAL statement_timeout = 0; SELECT pg_advisory_xact_lock(7403, 1)");
      conn_->run(kPgTables1);
      const PgResult cur = conn_->run("SELECT value FROM meta WHERE key = 'format'");
      const int version = cur.rows() ? version_of(cur.text(0, 0)) : 0;
      if (version < 2) {
        conn_->run(kPgTables2);
        if (version == 1) conn_->run(kPgBackfill2);
        conn_->run("INSERT INTO meta(key, value) VALUES('format', $1) ON CONFLICT (key) DO UPDATE SET value = $1",
                   {std::string(kStoreFormat2)});
        conn_->run("INSERT INTO meta(key, value) VALUES('store_id', $1) ON CONFLICT (key) DO NOTHING",
                   {pg_new_store_id()});
      }
      conn_->run("COMMIT");
    } catch (...) {
      try {
        conn_->run("ROLLBACK");
      } catch (...) {
      }
      throw;
    }
    version_ = 2;
    read_store_id();
  }

  std::string url_;
  PgOptions options_;
  std::unique_ptr<PgConn> conn_;
  std::unique_ptr<PgConn> holder_;
  int version_ = 2;
  std::string store_id_;
  std::set<std::string> claimed_;
};

}  // namespace

std::unique_ptr<StoreBackend> open_postgres_store(const std::string& url, StoreAccess access,
                                                  const PgOptions& options) {
  return std::make_unique<PgBackend>(url, access, options);
}

}  // namespace mark
