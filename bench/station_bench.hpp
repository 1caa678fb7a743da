#pragma once
// What the station's figure programs share (prog_station_tcp.cpp, prog_station_board_io.cpp):
// issue 22's 20-character serial job ("SN " + 17 digits), the station's arguments for it, and
// the quantile they report.
#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "marker/cli/mark_job.hpp"

namespace mark::bench {

inline constexpr const char* kSerial20Job = R"({
  "format": "marker-job/1", "head": "SL10", "time_zone": "UTC",
  "counters": {"serial": {"start": 1, "width": 17}},
  "pens": {"fine": {"speed_mm_s": 2000, "power_pct": 100, "frequency_khz": 40}},
  "objects": [{"name": "serial", "pen": "fine", "template": "SN {serial}", "height_mm": 2, "x_mm": -30, "y_mm": 0}]
})";

// `marker serve`'s arguments for kSerial20Job written as `dir`/serial20.json, with a SQLite store
// beside it, on `device` (virtual time unless `real_time`).
inline cli::MarkJobArgs serial20_args(const std::filesystem::path& dir, bool real_time, const std::string& device) {
  cli::MarkJobArgs a;
  a.job = (dir / "serial20.json").string();
  a.store.store = (dir / "bench.sqlite").string();
  a.station = "bench";
  a.create_counters = true;
  a.virtual_time = !real_time;
  a.device = device;
  return a;
}

// The q-quantile (0–1) of `v`, nearest rank below.
inline double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

}  // namespace mark::bench
