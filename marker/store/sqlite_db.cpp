#include "marker/store/sqlite_db.hpp"

#include <chrono>
#include <thread>

namespace mark {
namespace {

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

StoreErrorKind sqlite_error_kind(int code) {
  switch (code & 0xff) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED: return StoreErrorKind::busy;
    case SQLITE_FULL: return StoreErrorKind::full;
    case SQLITE_IOERR: return StoreErrorKind::io;
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB: return StoreErrorKind::corrupt;
    case SQLITE_CONSTRAINT: return StoreErrorKind::constraint;
    case SQLITE_INTERRUPT: return StoreErrorKind::cancelled;
    case SQLITE_CANTOPEN: return StoreErrorKind::io;
    default: return StoreErrorKind::other;
  }
}

SqliteDb::SqliteDb(const std::string& path, int flags, const char* vfs, std::string name)
    : name_(name.empty() ? path : std::move(name)) {
  if (sqlite3_open_v2(path.c_str(), &db_, flags, vfs) != SQLITE_OK) {
    // SQLite hands back a handle even when the open fails (the message is in it), and no
    // destructor runs for a constructor that throws: it is closed here once the message is
    // read (the ASan run of the tests found it leaking).
    try {
      fail("cannot open");
    } catch (...) {
      sqlite3_close_v2(db_);
      db_ = nullptr;
      throw;
    }
  }
  sqlite3_extended_result_codes(db_, 1);
}

SqliteDb::~SqliteDb() {
  if (db_) sqlite3_close_v2(db_);
}

void SqliteDb::set_busy_wait(int timeout_ms, std::function<bool()> cancel) {
  timeout_ms_ = timeout_ms;
  cancel_ = std::move(cancel);
  sqlite3_busy_handler(db_, &SqliteDb::on_busy, this);
}

int SqliteDb::on_busy(void* p, int count) {
  auto* self = static_cast<SqliteDb*>(p);
  if (count == 0) {
    self->wait_started_ns_ = now_ns();
    self->cancelled_ = false;
  }
  if (self->cancel_ && self->cancel_()) {
    self->cancelled_ = true;
    return 0;
  }
  if (now_ns() - self->wait_started_ns_ >= std::int64_t{self->timeout_ms_} * 1'000'000) return 0;
  std::this_thread::sleep_for(std::chrono::milliseconds(count < 10 ? 1 : 5));
  return 1;
}

void SqliteDb::fail(const std::string& what) const {
  const int code = db_ ? sqlite3_extended_errcode(db_) : SQLITE_CANTOPEN;
  StoreErrorKind kind = sqlite_error_kind(code);
  std::string reason = db_ ? sqlite3_errmsg(db_) : "out of memory";
  if (kind == StoreErrorKind::busy) {
    if (cancelled_) {
      kind = StoreErrorKind::cancelled;
      reason = "cancelled while waiting for another process's lock";
    } else {
      reason = "locked by another process for more than " + std::to_string(timeout_ms_) + " ms";
    }
  } else if (kind == StoreErrorKind::corrupt) {
    reason += " — the store is damaged: see `marker store check`, restore a backup (docs/store.md)";
  }
  throw StoreError("serial store " + name_ + ": " + what + ": " + reason, kind);
}

void SqliteDb::exec(const char* sql) const {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &err) != SQLITE_OK) {
    sqlite3_free(err);
    fail("statement");
  }
}

SqliteStmt::SqliteStmt(const SqliteDb& db, const std::string& sql) : db_(db) {
  if (sqlite3_prepare_v2(db.get(), sql.c_str(), static_cast<int>(sql.size()), &s_, nullptr) != SQLITE_OK)
    db.fail("prepare");
}

SqliteStmt::~SqliteStmt() { sqlite3_finalize(s_); }

SqliteStmt& SqliteStmt::bind(int i, std::int64_t v) {
  sqlite3_bind_int64(s_, i, v);
  return *this;
}

SqliteStmt& SqliteStmt::bind(int i, const std::string& v) {
  sqlite3_bind_text(s_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
  return *this;
}

SqliteStmt& SqliteStmt::bind_null(int i) {
  sqlite3_bind_null(s_, i);
  return *this;
}

bool SqliteStmt::step() {
  const int rc = sqlite3_step(s_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  db_.fail("statement");
}

void SqliteStmt::finish() {
  while (step()) {
  }
}

std::int64_t SqliteStmt::i64(int c) const { return sqlite3_column_int64(s_, c); }
bool SqliteStmt::null(int c) const { return sqlite3_column_type(s_, c) == SQLITE_NULL; }
std::string SqliteStmt::text(int c) const {
  const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(s_, c));
  return p ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(s_, c))) : std::string();
}

}  // namespace mark
