#pragma once
// Shared by the serial-store suites: a fresh SQLite store in a temporary folder, a counter spec,
// a render function, and the consistency check every suite ends with.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "marker/store/open_store.hpp"
#include "marker/store/serial_store.hpp"

namespace mark::test {

inline std::filesystem::path fresh_store_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("marker-store-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline CounterSpec plain_counter(const std::string& name = "sn", std::int64_t start = 1,
                                 std::int64_t step = 1) {
  CounterSpec s;
  s.name = name;
  s.start = start;
  s.step = step;
  s.time_zone = TimeZone::named("UTC");
  return s;
}

// One object "serial" = "SN <value>", carrying the serial field (so the marked-text index
// guards it).
inline RenderObjects render_sn(const std::string& counter = "sn") {
  return [counter](const std::map<std::string, std::int64_t>& serials) {
    return std::vector<ObjectText>{{"serial", "SN " + std::to_string(serials.at(counter)), true}};
  };
}

// The counters a test marks with, created in the store (a counter exists only once created).
inline void create_counters(SerialStore& store, const std::map<std::string, CounterSpec>& counters,
                            const std::string& station = "test") {
  MarkContext ctx;
  ctx.station = station;
  store.create_missing(counters, ShiftTable{}, ctx);
}

// Every issued value exactly once, each belonging to exactly one audit row that names it; every
// row closed. Returns the values issued for `counter`, sorted.
inline std::vector<std::int64_t> check_store_consistent(SerialStore& store,
                                                        const std::string& counter) {
  std::vector<std::int64_t> values;
  std::set<std::tuple<std::string, std::int64_t, std::int64_t, std::int64_t>> keys;
  std::map<std::int64_t, AuditRow> rows;
  for (AuditRow& r : store.log()) rows.emplace(r.id, std::move(r));
  std::map<std::int64_t, int> issues_per_row;
  for (const auto& [issue, mark_id] : store.issues(counter)) {
    EXPECT_TRUE(keys.insert({issue.period, issue.cycle, issue.value, issue.repeat}).second)
        << "value " << issue.value << " issued twice";
    values.push_back(issue.value);
    const auto row = rows.find(mark_id);
    EXPECT_NE(row, rows.end()) << "value " << issue.value << " has no audit row";
    if (row != rows.end()) {
      EXPECT_EQ(row->second.mark.serials.at(counter), issue.value);
      ++issues_per_row[mark_id];
    }
  }
  for (const auto& [id, row] : rows) {
    if (row.mark.kind == AuditKind::mark || row.mark.kind == AuditKind::reserve) {
      EXPECT_EQ(issues_per_row[id], row.mark.serials.count(counter) ? 1 : 0) << "row " << id;
    }
  }
  std::sort(values.begin(), values.end());
  return values;
}

}  // namespace mark::test
