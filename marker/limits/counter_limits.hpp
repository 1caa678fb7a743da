#pragma once
// What a serial counter accepts, wherever it is given (a job file's counters, `marker job new`):
// values over the whole signed 64-bit range the store keeps.
#include <cstdint>

#include "marker/limits/value_range.hpp"

namespace mark {

inline const WholeRange kCounterValueRange{0, INT64_MAX};          // start, limit
inline const WholeRange kCounterStepRange{-INT64_MAX, INT64_MAX};  // negative counts down
inline const WholeRange kMarksPerSerialRange{1, 1'000'000};
inline const WholeRange kCounterWidthRange{0, 64};                 // digits; 0: as many as needed
// One reservation issues at most this many values (one audit row each).
inline const WholeRange kReserveCountRange{1, 1'000'000};
// Parts one `mark --job` marks (each with its own serial numbers), and an audit row's id.
inline const WholeRange kPartCountRange{1, 1'000'000'000};
inline const WholeRange kAuditRowRange{1, INT64_MAX};

}  // namespace mark
