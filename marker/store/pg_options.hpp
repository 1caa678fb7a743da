#pragma once
// How long a PostgreSQL store waits (libpq stays out of the headers the store's users see).
namespace mark {

struct PgOptions {
  int lock_timeout_ms = 2000;        // a row or table another session holds
  int statement_timeout_ms = 30000;  // any statement of a write transaction
  int connect_timeout_s = 5;
};

}  // namespace mark
