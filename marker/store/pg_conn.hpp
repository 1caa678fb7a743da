#pragma once
// One PostgreSQL connection for the store (libpq). Every statement runs asynchronously: while
// the server works or waits for a lock, the client polls its cancel function and sends
// PQcancel when it says so (Ctrl-C), so nothing blocks without a way out. The session waits
// at most lock_timeout for a row another session holds and statement_timeout for a statement;
// every failure is a StoreError whose kind comes from the SQLSTATE (lock timeout: busy, the
// connection gone: connection, a key: constraint, disk full: full).
#include <libpq-fe.h>

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>

#include "marker/store/pg_options.hpp"
#include "marker/store/store_error.hpp"

namespace mark {

class PgResult {
 public:
  explicit PgResult(PGresult* r = nullptr) : r_(r) {}
  ~PgResult() { PQclear(r_); }
  PgResult(PgResult&& o) noexcept : r_(o.r_) { o.r_ = nullptr; }
  PgResult& operator=(PgResult&& o) noexcept;
  PgResult(const PgResult&) = delete;
  int rows() const { return r_ ? PQntuples(r_) : 0; }
  bool null(int row, int c) const { return PQgetisnull(r_, row, c); }
  std::string text(int row, int c) const { return PQgetvalue(r_, row, c); }
  std::int64_t i64(int row, int c) const { return std::stoll(PQgetvalue(r_, row, c)); }
  PGresult* get() const { return r_; }
  PGresult* release() {
    PGresult* r = r_;
    r_ = nullptr;
    return r;
  }
  explicit operator bool() const { return r_ != nullptr; }

 private:
  PGresult* r_;
};

using PgParams = std::initializer_list<std::optional<std::string>>;

class PgConn {
 public:
  // Throws StoreError (connection) naming the URL without its password.
  PgConn(const std::string& url, const PgOptions& options);
  ~PgConn();
  PgConn(const PgConn&) = delete;
  PgConn& operator=(const PgConn&) = delete;

  const std::string& describe() const { return describe_; }
  int backend_pid() const { return PQbackendPID(c_); }
  bool broken() const { return PQstatus(c_) != CONNECTION_OK; }
  void set_cancel(std::function<bool()> cancel) { cancel_ = std::move(cancel); }

  // Runs `sql` (several statements when it has no parameters); throws StoreError unless every
  // statement completed. The result of the last statement.
  PgResult run(const std::string& sql, PgParams params = {});
  PgResult run(const std::string& sql, const std::vector<std::optional<std::string>>& params);
  // Streams the rows of one query (single-row mode: constant memory); `row` returns false to
  // stop (the rest is read and dropped).
  void stream(const std::string& sql, const std::vector<std::optional<std::string>>& params,
              const std::function<bool(const PgResult&)>& row);
  // Connects again (PQreset) and sets up the session. Throws StoreError (connection).
  void reset();

 private:
  void send(const std::string& sql, const std::vector<std::optional<std::string>>& params, bool single_row);
  // Waits for the next result, cancelling the statement when asked; nullptr when done.
  PGresult* next_result();
  [[noreturn]] void fail(PGresult* r);
  void setup_session();

  std::string url_;
  PgOptions options_;
  PGconn* c_ = nullptr;
  std::string describe_;
  std::function<bool()> cancel_;
  bool cancel_sent_ = false;
};

// libpq's message up to its first line; the URL without a password.
std::string pg_first_line(const std::string& s);
std::string pg_redacted(const std::string& url);

}  // namespace mark
