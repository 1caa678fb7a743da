#pragma once
// What the station's figure programs share (prog_station_tcp.cpp, prog_station_modbus.cpp,
// prog_station_board_io.cpp): issue 22's 20-character serial job ("SN " + 17 digits), the
// station's arguments for it, the quantile they report, and trigger-to-first-sample broken down.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "marker/cli/emulated_lmc_device.hpp"
#include "marker/cli/mark_job.hpp"
#include "marker/production/part_run.hpp"

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

// The board's first sample of a part triggered at `trigger`: when ExecuteList reached the
// emulated board (it runs nothing of its list before: driver/lmc/session.cpp), on the steady
// clock (WireRecord::arrived); nothing when none came after `trigger`.
inline std::optional<std::chrono::steady_clock::time_point> board_first_sample(
    const lmc::EmulatedBoard& board, std::chrono::steady_clock::time_point trigger) {
  for (const lmc::WireRecord& w : board.wire())
    if (!w.packet && w.single.opcode() == static_cast<std::uint16_t>(lmc::Op::ExecuteList) && w.arrived >= trigger)
      return w.arrived;
  return std::nullopt;
}

// Trigger to first sample, part by part, and where it went (PartResult::times, all on the
// steady clock): the interface to the runner (the adapter, the station's lock, mark_next), the
// compile inside the allocation (render, layout, plan), the rest of the allocation (the store's
// transaction and durable commit), and the commit to the device's first block (begin_job, the
// stream's start). `first` is when the device got its first block (DrainStats first_write).
class TriggerSteps {
 public:
  using TimePoint = std::chrono::steady_clock::time_point;
  void add(TimePoint trigger, const PartResult& part, TimePoint first) {
    total_.push_back(ms(trigger, first));
    to_runner_.push_back(ms(trigger, part.times.started));
    compile_.push_back(1e3 * part.times.compile_s);
    store_.push_back(ms(part.times.started, part.times.committed) - 1e3 * part.times.compile_s);
    to_device_.push_back(ms(part.times.committed, first));
  }
  const std::vector<double>& total() const { return total_; }
  // `trigger`: what the clock starts at, for the first line.
  void print(const char* trigger) const {
    line("trigger to first sample", total_, trigger);
    line("of which to the runner", to_runner_, "the interface, the station's lock, mark_next");
    line("of which the compile", compile_, "inside the allocation: render, layout, plan");
    line("of which the store", store_, "the allocation's transaction and durable commit, less the compile");
    line("of which to the device", to_device_, "the commit to the first block: begin_job, the stream's start");
  }

 private:
  static double ms(TimePoint from, TimePoint to) { return std::chrono::duration<double, std::milli>(to - from).count(); }
  static void line(const char* what, const std::vector<double>& v, const char* note) {
    std::printf("  %-26s median %.3f ms  p99 %.3f ms  (%s)\n", what, quantile(v, 0.5), quantile(v, 0.99), note);
  }
  std::vector<double> total_, to_runner_, compile_, store_, to_device_;
};

}  // namespace mark::bench
