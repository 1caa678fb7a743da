#include "marker/store/sqlite_schema.hpp"

#include <random>

#include "marker/store/store_format.hpp"

namespace mark {
namespace {

// Version 1's tables, as stores of that version have them.
constexpr const char* kTables1 = R"SQL(
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

// What version 2 adds: the marked texts (unique), the data-list rows taken (unique), a
// re-mark's reason and the store's note on a row, and the indexes `log --serial` / `--text`
// and the re-mark links read through.
constexpr const char* kColumns2 = R"SQL(
ALTER TABLE marks ADD COLUMN reason TEXT NOT NULL DEFAULT '';
ALTER TABLE marks ADD COLUMN note TEXT NOT NULL DEFAULT '';
ALTER TABLE marks ADD COLUMN data_list TEXT;
ALTER TABLE marks ADD COLUMN data_row INTEGER;
)SQL";

constexpr const char* kTables2 = R"SQL(
CREATE TABLE IF NOT EXISTS marked_texts(
  text TEXT PRIMARY KEY, object TEXT NOT NULL, mark_id INTEGER NOT NULL REFERENCES marks(id));
CREATE TABLE IF NOT EXISTS data_rows(
  row_key TEXT PRIMARY KEY, list TEXT NOT NULL, row INTEGER NOT NULL,
  mark_id INTEGER NOT NULL REFERENCES marks(id));
CREATE INDEX IF NOT EXISTS issues_value ON issues(value);
CREATE INDEX IF NOT EXISTS marks_remark ON marks(remark_of);
CREATE INDEX IF NOT EXISTS marked_texts_mark ON marked_texts(mark_id);
CREATE TRIGGER IF NOT EXISTS marked_texts_no_update BEFORE UPDATE ON marked_texts
  BEGIN SELECT RAISE(ABORT, 'marked texts are append-only'); END;
CREATE TRIGGER IF NOT EXISTS marked_texts_no_delete BEFORE DELETE ON marked_texts
  BEGIN SELECT RAISE(ABORT, 'marked texts are append-only'); END;
CREATE TRIGGER IF NOT EXISTS data_rows_no_update BEFORE UPDATE ON data_rows
  BEGIN SELECT RAISE(ABORT, 'data rows taken are append-only'); END;
CREATE TRIGGER IF NOT EXISTS data_rows_no_delete BEFORE DELETE ON data_rows
  BEGIN SELECT RAISE(ABORT, 'data rows taken are append-only'); END;
)SQL";

// A version 1 store did not know which objects carried a serial field: every object text of a
// row that consumed a number goes into the index (the first row keeps a text marked twice).
constexpr const char* kBackfill2 = R"SQL(
INSERT OR IGNORE INTO marked_texts(text, object, mark_id)
  SELECT json_extract(o.value, '$.text'), json_extract(o.value, '$.name'), m.id
  FROM marks m, json_each(m.objects) o
  WHERE m.kind = 'mark' AND m.serials <> '{}' ORDER BY m.id;
)SQL";

std::string new_store_id() {
  std::random_device rd;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string id;
  for (int i = 0; i < 8; ++i) {
    const unsigned v = rd();
    for (int k = 0; k < 4; ++k) id += kHex[(v >> (4 * k)) & 15];
  }
  return id;
}

std::string meta(const SqliteDb& db, const char* key) {
  SqliteStmt s(db, std::string("SELECT value FROM meta WHERE key = '") + key + "'");
  return s.step() ? s.text(0) : std::string();
}

void put_meta(const SqliteDb& db, const char* key, const std::string& value) {
  SqliteStmt s(db, "INSERT OR REPLACE INTO meta(key, value) VALUES(?1, ?2)");
  s.bind(1, std::string(key)).bind(2, value).finish();
}

bool has_table(const SqliteDb& db, const char* name) {
  SqliteStmt s(db, std::string("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = '") + name + "'");
  return s.step();
}

int version_of(const SqliteDb& db, const std::string& format) { return store_format_version(db.name(), format); }

}  // namespace

SqliteFormat create_or_upgrade(const SqliteDb& db) {
  db.exec("BEGIN IMMEDIATE");
  try {
    db.exec(kTables1);
    SqliteFormat f;
    const std::string format = meta(db, "format");
    f.version = format.empty() ? 0 : version_of(db, format);
    if (f.version < 2) {
      db.exec(kColumns2);
      db.exec(kTables2);
      if (f.version == 1) db.exec(kBackfill2);
      put_meta(db, "format", kStoreFormat2);
      put_meta(db, "store_id", new_store_id());
      f.version = 2;
    }
    f.store_id = meta(db, "store_id");
    db.exec("COMMIT");
    return f;
  } catch (...) {
    sqlite3_exec(db.get(), "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

SqliteFormat read_format(const SqliteDb& db) {
  SqliteFormat f;
  if (!has_table(db, "meta"))
    throw StoreError("serial store " + db.name() + " is not a serial store (no meta table)",
                     StoreErrorKind::corrupt);
  f.version = version_of(db, meta(db, "format"));
  f.store_id = meta(db, "store_id");
  return f;
}

}  // namespace mark
