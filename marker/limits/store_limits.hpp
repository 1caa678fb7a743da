#pragma once
// The serial store's settings that a user can give (mark --job, log, serial, store): how long
// a station waits for a locked store or a server, how often it tries again, how many audit
// rows `log` prints. One definition each, used by the command line and the docs.
#include "marker/limits/value_range.hpp"

namespace mark {

// SQLite: the longest wait for another writer's lock; PostgreSQL: lock_timeout.
inline const WholeRange kStoreWaitMsRange{0, 600'000};
inline constexpr int kStoreWaitMsDefault = 2000;
// PostgreSQL: statement_timeout (a statement running longer is cancelled).
inline const WholeRange kStoreStatementMsRange{100, 3'600'000};
inline constexpr int kStoreStatementMsDefault = 30000;
// Attempts of an allocation (on a locked store or a lost connection) and of an outcome write
// before the outcome stays in the journal only; the wait between attempts doubles from the
// first up to the last.
inline const WholeRange kStoreAttemptsRange{1, 20};
inline constexpr int kStoreAttemptsDefault = 3;
inline const WholeRange kStoreBackoffMsRange{0, 60'000};
inline constexpr int kStoreBackoffFirstMsDefault = 200;
inline constexpr int kStoreBackoffMaxMsDefault = 2000;
// `marker log --limit N`: the last N rows.
inline const WholeRange kLogLimitRange{1, 1'000'000'000};

}  // namespace mark
