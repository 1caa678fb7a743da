// The station's board trigger on the emulated LMC board (issue 22's figure "from an input edge
// on the emulated board"): station_tcp's 20-character serial job ("SN " + 17 digits) on
// `--device lmc-emulated` (virtual time unless --real-time) with a SQLite store in a temporary
// folder, `marker serve --trigger lmc-input:3 --signal ready=4,busy=5` in process (JobSource →
// Station → BoardIo on the board's ReadPort), the program raising input pin 3 on the emulated
// board once per part.
//
//   station_board_io [--parts N] [--debounce-ms MS] [--min-pulse-ms MS] [--real-time]
//
// Prints per part, median and p99:
// - edge → marking: the pin set on the board to the station entering `marking` (the poll, the
//   debounce and minimum pulse, mark_async);
// - edge → first sample, station_tcp's definition on this board: the pin set to the board's
//   first sample, which is when ExecuteList reaches it (the board runs nothing of its list
//   before: driver/lmc/session.cpp), read off the board's wire record on the same steady clock
//   (WireRecord::arrived); broken down as station_tcp's (station_bench.hpp TriggerSteps).
// Before each part the pin is low for ten polls, so every edge is a fresh one.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

#include "marker/cli/emulated_lmc_device.hpp"
#include "marker/cli/serve_board_io.hpp"
#include "bench/station_bench.hpp"
#include "marker/cli/serve_source.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using mark::bench::kSerial20Job;
using mark::bench::quantile;

void print(const char* what, const std::vector<double>& ms, const char* note = "") {
  std::printf("  %-26s median %.3f ms  p99 %.3f ms%s\n", what, quantile(ms, 0.5), quantile(ms, 0.99), note);
}

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("the marking station's board trigger on the emulated LMC board");
  int parts = 100;
  double debounce_ms = 5, min_pulse_ms = 5;
  bool real_time = false;
  app.add_option("--parts", parts, "input edges (one part each)")->check(CLI::Range(2, 100'000));
  app.add_option("--debounce-ms", debounce_ms, "--trigger-debounce-ms")->check(CLI::Range(0.0, 1000.0));
  app.add_option("--min-pulse-ms", min_pulse_ms, "--trigger-min-pulse-ms")->check(CLI::Range(0.0, 1000.0));
  app.add_flag("--real-time", real_time, "the board's clock in real time (default: virtual time)");
  CLI11_PARSE(app, argc, argv);

  const auto dir = std::filesystem::temp_directory_path() / ("station-board-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "serial20.json") << kSerial20Job;
  std::vector<double> marking_ms;
  mark::bench::TriggerSteps first;
  {
    mark::cli::JobSource source(mark::bench::serial20_args(dir, real_time, "lmc-emulated"));
    mark::Station station(source);
    std::mutex m;
    std::condition_variable cv;
    Clock::time_point marking_at{}, ended_at{};
    bool ended = false;
    station.add_listener([&](const mark::StationEvent& e) {
      std::lock_guard lock(m);
      if (e.part) {
        ended_at = Clock::now();
        ended = true;
        cv.notify_all();
      } else if (e.state == mark::StationState::marking) {
        marking_at = Clock::now();
      }
    });
    const mark::cli::BoardIoArgs args{"lmc-input:3", "ready=4,busy=5", debounce_ms, min_pulse_ms};
    auto io = mark::cli::open_board_io(station, source.device(), *mark::cli::parse_board_io(args), {});
    auto& board = dynamic_cast<mark::cli::EmulatedLmcDevice&>(source.device()).emulated_board();
    const auto polls_later = [&](std::size_t n) {
      const std::size_t until = board.state().read_ports + n;
      while (board.state().read_ports < until) std::this_thread::sleep_for(std::chrono::microseconds(200));
    };
    for (int i = 0; i < parts; ++i) {
      board.set_inputs(0);
      polls_later(10);
      {
        std::lock_guard lock(m);
        ended = false;
      }
      const auto t0 = Clock::now();
      board.set_inputs(1u << 3);
      std::unique_lock lock(m);
      if (!cv.wait_for(lock, std::chrono::seconds(30), [&] { return ended; })) {
        std::fprintf(stderr, "station_board_io: part %d: no part within 30 s of the edge\n", i + 1);
        return 1;
      }
      const auto marked = marking_at, end = ended_at;
      lock.unlock();  // the listener takes it under the station's lock: never the other way round
      const auto last = station.status().last;
      if (!last || last->outcome != mark::JobOutcome::done) {
        std::fprintf(stderr, "station_board_io: part %d did not end done\n", i + 1);
        return 1;
      }
      marking_ms.push_back(ms(marked - t0));
      const auto executed = mark::bench::board_first_sample(board, t0);
      if (!executed || *executed > end) {
        std::fprintf(stderr, "station_board_io: part %d: no ExecuteList reached the board\n", i + 1);
        return 1;
      }
      first.add(t0, *last, *executed);
    }
    if (io->triggers() != static_cast<std::uint64_t>(parts) || station.status().parts != static_cast<std::uint64_t>(parts)) {
      std::fprintf(stderr, "station_board_io: %llu triggers, %llu parts for %d edges\n",
                   static_cast<unsigned long long>(io->triggers()),
                   static_cast<unsigned long long>(station.status().parts), parts);
      return 1;
    }
    io.reset();
  }
  std::filesystem::remove_all(dir);
  std::printf("station_board_io: %d edges on input 3 of the emulated LMC board (%s), debounce %g ms, min pulse %g ms, "
              "polled every 1 ms\n",
              parts, real_time ? "real time" : "virtual time", debounce_ms, min_pulse_ms);
  print("edge to marking", marking_ms, "  (poll + debounce/min pulse + mark_async)");
  first.print("the pin set to ExecuteList on the board");
  return 0;
}
