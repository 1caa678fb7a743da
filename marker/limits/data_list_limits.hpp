#pragma once
// What a data list (a CSV file a job takes one row per part from) may hold: limits that keep a
// list in memory and a malformed file from exhausting it. Counted while parsing, so an oversize
// file is refused before anything is marked.
#include <cstdint>

#include "marker/limits/value_range.hpp"

namespace mark {

inline constexpr std::int64_t kDataListMaxBytes = 256LL << 20;  // the file
inline const WholeRange kDataListRowsRange{0, 10'000'000};       // data rows (the header aside)
inline const WholeRange kDataListColumnsRange{1, 256};
inline constexpr std::int64_t kDataFieldMaxBytes = 4096;        // one value

}  // namespace mark
