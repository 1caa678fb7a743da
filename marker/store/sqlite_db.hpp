#pragma once
// One SQLite connection and its statements, for the store's SQLite backend: every failure
// becomes a StoreError naming the store, with its kind from SQLite's result code (busy, full,
// i/o, damaged, a key). Waiting for another writer's lock is a busy handler that gives up after
// the store's timeout — or at once when the caller's cancel says so (Ctrl-C), instead of
// sqlite3_busy_timeout's wait that nothing can interrupt.
#include <sqlite3.h>

#include <cstdint>
#include <functional>
#include <string>

#include "marker/store/store_error.hpp"

namespace mark {

class SqliteDb {
 public:
  // Opens `path` with `flags` (SQLITE_OPEN_*) through `vfs` (nullptr: the default); `uri`:
  // `path` is a file: URI. Throws StoreError naming `name` (the path as the user gave it).
  SqliteDb(const std::string& path, int flags, const char* vfs = nullptr, std::string name = "");
  ~SqliteDb();
  SqliteDb(const SqliteDb&) = delete;
  SqliteDb& operator=(const SqliteDb&) = delete;

  sqlite3* get() const { return db_; }
  const std::string& name() const { return name_; }
  // Waits for another writer's lock at most `timeout_ms`, polling `cancel` (may be empty).
  void set_busy_wait(int timeout_ms, std::function<bool()> cancel);
  int busy_timeout_ms() const { return timeout_ms_; }

  // Throws the StoreError for the connection's last error, "serial store NAME: WHAT: reason".
  [[noreturn]] void fail(const std::string& what) const;
  void exec(const char* sql) const;

 private:
  static int on_busy(void* self, int count);

  sqlite3* db_ = nullptr;
  std::string name_;
  int timeout_ms_ = 0;
  std::function<bool()> cancel_;
  std::int64_t wait_started_ns_ = 0;
  mutable bool cancelled_ = false;  // the last busy wait ended by cancel
};

// A prepared statement; step() is true while there is a row.
class SqliteStmt {
 public:
  SqliteStmt(const SqliteDb& db, const std::string& sql);
  ~SqliteStmt();
  SqliteStmt(const SqliteStmt&) = delete;
  SqliteStmt& operator=(const SqliteStmt&) = delete;

  SqliteStmt& bind(int i, std::int64_t v);
  SqliteStmt& bind(int i, const std::string& v);
  SqliteStmt& bind_null(int i);
  bool step();
  // Steps to the end (an INSERT, an UPDATE … RETURNING whose rows are read already).
  void finish();
  std::int64_t i64(int c) const;
  bool null(int c) const;
  std::string text(int c) const;

 private:
  const SqliteDb& db_;
  sqlite3_stmt* s_ = nullptr;
};

// The kind of a StoreError for an SQLite result code.
StoreErrorKind sqlite_error_kind(int code);

}  // namespace mark
