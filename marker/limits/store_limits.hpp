#pragma once
// The serial store's limits that a user can set (mark --job, log, serial, store): how long a
// station waits for a locked store or a server and how often it tries again; the library's
// defaults (open_store.hpp) and the options (production_settings.hpp) are declared from them.
#include "marker/limits/value_range.hpp"

namespace mark {

// SQLite: the longest wait for another writer's lock; PostgreSQL: lock_timeout.
inline constexpr WholeRange kStoreWaitMsRange{0, 600'000};
inline constexpr int kStoreWaitMsDefault = 2000;
// PostgreSQL: statement_timeout (a statement running longer is cancelled).
inline constexpr WholeRange kStoreStatementMsRange{100, 3'600'000};
inline constexpr int kStoreStatementMsDefault = 30000;
// Attempts of an allocation (on a locked store or a lost connection) and of an outcome write
// before the outcome stays in the journal only; the wait between attempts doubles from the
// first up to the last.
inline constexpr WholeRange kStoreAttemptsRange{1, 20};
inline constexpr int kStoreAttemptsDefault = 3;
inline constexpr WholeRange kStoreBackoffMsRange{0, 60'000};
inline constexpr int kStoreBackoffFirstMsDefault = 200;
inline constexpr int kStoreBackoffMaxMsDefault = 2000;

}  // namespace mark
