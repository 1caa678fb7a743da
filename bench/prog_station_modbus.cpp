// Trigger to first sample from the Modbus start coil (issue 22's figure "the same from the Modbus
// start coil with pymodbus as the client"): station_tcp's 20-character serial job ("SN " + 17
// digits) on the simulated scanner (virtual time unless --real-time) with a SQLite store in a
// temporary folder, `marker serve --modbus` in process (JobSource → Station → ModbusServer), and
// a pymodbus client (bench/station_modbus_trigger.py, /usr/bin/python3) writing the start coil
// once per part and waiting for busy to clear.
//
//   station_modbus [--parts N] [--real-time]
//
// The same definition as station_tcp: the client's clock just before its write of the start
// coil to the drain's first block to the device (DrainStats first_write). The client prints
// time.monotonic_ns(), which is CLOCK_MONOTONIC; std::chrono::steady_clock is CLOCK_MONOTONIC on
// Linux with libstdc++, so the two subtract directly across the processes — checked on every
// part by a sanity bound (0 < latency < 1 s: a clock of another epoch would be off by hours).
// Each part is matched to its write by order and by its serial (input registers 2–3).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <vector>

#include "bench/station_bench.hpp"
#include "marker/cli/serve_source.hpp"
#include "marker/station/modbus_server.hpp"

namespace {

struct Ended {
  mark::PartResult part;
  std::int64_t serial = 0;
  std::chrono::steady_clock::time_point first_write{};
  bool done = false;
};

}  // namespace

int main(int argc, char** argv) {
  static_assert(std::chrono::steady_clock::is_steady);
  CLI::App app("trigger to first sample from the station's Modbus start coil, pymodbus as the client");
  int parts = 200;
  bool real_time = false;
  app.add_option("--parts", parts, "start coil writes (one part each)")->check(CLI::Range(2, 100'000));
  app.add_flag("--real-time", real_time, "drain at the scanner's clock (default: virtual time)");
  CLI11_PARSE(app, argc, argv);

  const auto dir = std::filesystem::temp_directory_path() / ("station-modbus-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "serial20.json") << mark::bench::kSerial20Job;
  mark::bench::TriggerSteps first;
  std::string failure;
  {
    mark::cli::JobSource source(mark::bench::serial20_args(dir, real_time, "sim"));
    mark::Station station(source);
    std::mutex m;
    std::vector<Ended> ended;
    station.add_listener([&](const mark::StationEvent& e) {
      if (!e.part) return;
      const auto& first = e.part->objects.empty() ? mark::JobResult{} : e.part->objects.front().result;
      std::lock_guard lock(m);
      ended.push_back({*e.part, e.part->serials.count("serial") ? e.part->serials.at("serial") : -1,
                       first.drain.first_write, e.part->good()});
    });
    mark::ModbusServer server(station, mark::parse_listen_address("127.0.0.1:0", "--modbus"), {}, 8);
    const std::string command = std::string("/usr/bin/python3 ") + MARKER_SOURCE_DIR +
                                "/bench/station_modbus_trigger.py " + std::to_string(server.port()) + " " +
                                std::to_string(parts);
    FILE* client = ::popen(command.c_str(), "r");
    if (!client) return std::perror("station_modbus: popen"), 1;
    char line[256];
    int i = 0;
    bool end = false;
    while (failure.empty() && std::fgets(line, sizeof line, client)) {
      long long sent_ns = 0, serial = 0;
      if (std::string(line) == "end\n") {
        end = true;
        break;
      }
      if (std::sscanf(line, "%lld %lld", &sent_ns, &serial) != 2) {
        failure = "the client: " + std::string(line);
        break;
      }
      std::lock_guard lock(m);
      if (i >= static_cast<int>(ended.size())) {
        failure = "the client saw busy clear before part " + std::to_string(i + 1) + " ended";
        break;
      }
      const Ended& e = ended[static_cast<std::size_t>(i++)];
      const double ms = (std::chrono::duration<double, std::milli>(e.first_write.time_since_epoch()).count() -
                         static_cast<double>(sent_ns) / 1e6);
      if (!e.done || e.serial != serial)
        failure = "part " + std::to_string(i) + ": serial " + std::to_string(e.serial) + " (" +
                  (e.done ? "done" : "not done") + "), the client read " + std::to_string(serial);
      else if (!(ms > 0 && ms < 1000))
        failure = "part " + std::to_string(i) + ": " + std::to_string(ms) +
                  " ms from the write to the first sample: the clocks are not the same monotonic clock";
      first.add(std::chrono::steady_clock::time_point(std::chrono::nanoseconds(sent_ns)), e.part, e.first_write);
    }
    const int status = ::pclose(client);
    if (failure.empty() && (!end || status != 0 || i != parts))
      failure = "the client ended after " + std::to_string(i) + " of " + std::to_string(parts) + " parts";
    server.stop();
    station.wait_idle();
  }
  std::filesystem::remove_all(dir);
  if (!failure.empty()) {
    std::fprintf(stderr, "station_modbus: %s\n", failure.c_str());
    return 1;
  }
  std::printf("station_modbus: %d parts (%s), 20-character serial, pymodbus writing the start coil\n", parts,
              real_time ? "real time" : "virtual time");
  first.print("the client's clock before its coil write to the device's first block");
  return 0;
}
