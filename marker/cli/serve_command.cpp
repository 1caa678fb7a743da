// `marker serve --job FILE [--device D] [--listen 127.0.0.1:PORT] [--http 127.0.0.1:PORT]
//  [--store PATH|URL] [--station NAME] [--set NAME=VALUE …] [--create-counters] [--virtual-time]
//  [--modbus HOST:PORT [--modbus-allow ADDR[/BITS] …]] [--max-connections N]
//  [--trigger lmc-input:BIT] [--signal ready=B,busy=B,done=B,error=B] [--trigger-debounce-ms MS]
//  [--trigger-min-pulse-ms MS] [--token FILE]`: the marking station (docs/station.md). Loads the job once, keeps the
// device open and marks on command over the TCP line protocol and, with --http, over HTTP +
// JSON, with --modbus over Modbus TCP (marker/station/). One log line per event on stderr. SIGTERM / Ctrl-C: a part in progress
// is aborted with the laser off and recorded aborted (its numbers void), every connection is
// closed, exit 0.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <mutex>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/serve_board_io.hpp"
#include "marker/cli/serve_source.hpp"
#include "marker/limits/device_settings.hpp"
#include "marker/limits/marking_settings.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/limits/station_settings.hpp"
#include "marker/station/http_server.hpp"
#include "marker/station/modbus_server.hpp"
#include "marker/station/station_token.hpp"
#include "marker/station/tcp_server.hpp"

namespace mark::cli {
namespace {

struct ServeArgs {
  MarkJobArgs job;
  std::string listen;      // the settings' defaults (add_setting)
  std::string http;        // empty: no HTTP interface
  std::string modbus;      // empty: no Modbus interface
  std::vector<std::string> modbus_allow;
  std::string token_file;  // empty: no token, loopback only
  int max_connections = 0;
  BoardIoArgs board_io;  // --trigger, --signal
};

// One line per event: UTC time, then what happened (a line at a time from any thread).
void log_line(const std::string& event) {
  static std::mutex m;
  const auto now = std::chrono::system_clock::now();
  const std::time_t t = std::chrono::system_clock::to_time_t(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%S", &tm);
  std::lock_guard lock(m);
  std::fprintf(stderr, "marker: serve: %s.%03dZ %s\n", stamp, static_cast<int>(ms), event.c_str());
  std::fflush(stderr);
}

int serve(const ServeArgs& a) {
  const std::string token = a.token_file.empty() ? std::string() : read_station_token(a.token_file, "--token");
  const ListenAddress address = parse_listen_address(a.listen, "--listen", !token.empty());
  std::optional<ListenAddress> http_address;
  if (!a.http.empty()) http_address = parse_listen_address(a.http, "--http", !token.empty());
  std::optional<ListenAddress> modbus_address;
  if (!a.modbus.empty()) modbus_address = parse_host_port(a.modbus, "--modbus");
  std::vector<AllowedNet> allow;
  for (const std::string& net : a.modbus_allow) allow.push_back(parse_allowed_net(net, "--modbus-allow"));
  if (!allow.empty() && !modbus_address) throw InputError("--modbus-allow: give --modbus HOST:PORT too");
  if (modbus_address) check_modbus_access(*modbus_address, allow);  // before the store and device open
  const std::optional<BoardIoOptions> board_io_options = parse_board_io(a.board_io);
  JobSource source(a.job);
  Station station(source, log_line);
  std::unique_ptr<BoardIo> board_io;
  if (board_io_options) board_io = open_board_io(station, source.device(), *board_io_options, log_line);
  TcpServer server(station, address, a.max_connections, log_line, token);
  std::unique_ptr<HttpServer> http;
  if (http_address) {
    http = std::make_unique<HttpServer>(station, *http_address, log_line, token);
    log_line("http on " + http_address->host + ":" + std::to_string(http->port()) + " (operator page: http://" +
             http_address->host + ":" + std::to_string(http->port()) + "/)");
  }
  std::unique_ptr<ModbusServer> modbus;
  if (modbus_address) {
    modbus = std::make_unique<ModbusServer>(station, *modbus_address, allow, a.max_connections, log_line);
    log_line("modbus on " + modbus_address->host + ":" + std::to_string(modbus->port()));
  }
  log_line("listening on " + address.host + ":" + std::to_string(server.port()) + " job " + a.job.job);
  server.serve([] { return interrupt_flag().requested(); });
  if (modbus) modbus->stop();  // first: no start coil can begin a part after the abort below
  if (board_io) board_io->stop();  // nor an input edge
  // SIGTERM: the laser off and a part in progress recorded aborted before anything closes.
  const StationState was = station.abort();
  log_line(std::string("stopping (state ") + std::string(to_string(was)) + ")");
  server.stop();
  station.wait_idle();
  if (http) http->stop();  // after the part ended: the event stream tells it before it closes
  log_line("stopped");
  return 0;
}

}  // namespace

Command make_serve_command() {
  auto a = std::make_shared<ServeArgs>();
  return Command(
      [=](CLI::App& app) {
        auto* sub = app.add_subcommand("serve", "the marking station: mark the parts of a job on command over TCP");
        MarkJobArgs& p = a->job;
        sub->add_option("--job", p.job, "the job file the station marks")->required();
        add_setting(*sub, kDevice, p.device);
        add_setting(*sub, kListen, a->listen);
        add_setting(*sub, kHttp, a->http);
        add_setting(*sub, kModbus, a->modbus);
        add_setting(*sub, kModbusAllow, a->modbus_allow);
        add_setting(*sub, kToken, a->token_file);
        add_setting(*sub, kMaxConnections, a->max_connections);
        add_setting(*sub, kTrigger, a->board_io.trigger);
        add_setting(*sub, kSignal, a->board_io.signal);
        add_setting(*sub, kTriggerDebounce, a->board_io.debounce_ms);
        add_setting(*sub, kTriggerMinPulse, a->board_io.min_pulse_ms);
        add_setting(*sub, kSet, p.sets);
        add_setting(*sub, kStation, p.station);
        add_setting(*sub, kCreateCounters, p.create_counters);
        add_setting(*sub, kVirtualTime, p.virtual_time);
        add_store_options(*sub, p.store, true);
        return sub;
      },
      [=] { return serve(*a); });
}

}  // namespace mark::cli
