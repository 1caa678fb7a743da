#pragma once
// Faults injected into the serial store, so tests (and `marker mark --job --inject
// store@STEP:KIND`) see what a part's record becomes when the store fails at each step. The
// backends make each fault happen for real (store_backend.hpp, provoke()): a second connection
// holding the write lock, the disk reporting full under SQLite, the server connection
// terminated — not an exception thrown in place of the store.
#include <optional>
#include <string>
#include <string_view>

namespace mark {

// The store's steps for a part: its allocation (before the laser fires) and its outcome.
enum class StoreStep { allocate, outcome };

enum class StoreFaultKind {
  locked,   // another connection holds the lock (SQLite: the write lock; PostgreSQL: the rows)
  full,     // the disk is full (SQLite: every write of the store's files fails with SQLITE_FULL)
  io,       // the disk fails (SQLite: every write fails with SQLITE_IOERR)
  stopped,  // the server goes away (PostgreSQL: the connection is terminated)
};

std::string_view to_string(StoreStep s);
std::string_view to_string(StoreFaultKind k);
std::optional<StoreStep> parse_store_step(std::string_view name);
std::optional<StoreFaultKind> parse_store_fault(std::string_view name);

// Which attempts fail: of the `part`-th call of `step` (1: the first part), the first
// `attempts` attempts (0: every one, so the step fails for good).
struct StoreFaultPlan {
  StoreStep step = StoreStep::outcome;
  StoreFaultKind kind = StoreFaultKind::locked;
  int part = 1;
  int attempts = 0;
};

}  // namespace mark
