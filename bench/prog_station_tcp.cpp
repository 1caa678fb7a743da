// The station over its TCP line protocol on loopback (issue 22's figures): a 20-character
// serial job ("SN " + 17 digits) on the simulated scanner with a SQLite store in a temporary
// folder, `marker serve`'s parts (JobSource → Station → TcpServer) in process, one client
// sending MARK back to back.
//
//   station_tcp [--parts N] [--real-time] [--http] [--clients N] [--device sim|lmc-emulated]
//
// --device lmc-emulated: the emulated LMC board instead of the simulated scanner (whose
// begin_job sizes its dose raster for the part: the simulator's modelling, not the station's);
// its first sample is ExecuteList reaching the board (station_bench.hpp board_first_sample).
//
// --http: an HttpServer on the same station too, and an httplib::Client (keep-alive) sending
// POST /api/mark after each MARK, alternately, so both see the same store and machine load;
// then STATUS against GET /api/status (the adapters alone, without a part).
//
// --clients N (N > 1): the load run of issue 22. N connections send MARK at once until N parts
// are done (a `busy` reply waits 1 ms, as a PLC polls, and tries again); then the store must hold
// exactly one done row per OK reply and no serial twice, and the process's RSS after the first
// part, after a tenth of them (the allocator's per-thread arenas grown) and after the last is
// printed: flat memory is the last against the tenth.
//
// Prints per MARK: the round trip (client's send to the reply line), and trigger to first
// sample: the client's send to the drain's first block to the device (DrainStats first_write, on
// the same steady clock: the durable serial commit, the compile and begin_job are in it), broken
// down (station_bench.hpp TriggerSteps); then marks per second. Virtual time by default (the drain as fast as the scanner takes samples; the
// simulator's dose and quality figures after each part stay in the round trip and marks/s).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "bench/station_bench.hpp"
#include "marker/cli/serve_source.hpp"
#include "marker/station/http_server.hpp"
#include "marker/station/tcp_server.hpp"
#include "marker/store/open_store.hpp"
// Last: it brings <resolv.h>, whose `_res` macro breaks Eigen's headers included after it.
#include <httplib.h>

namespace {

using mark::bench::kSerial20Job;
using mark::bench::quantile;

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// One command line to the station and its reply line ("" when the connection ended).
std::string ask(int fd, std::string& buf, const std::string& command) {
  const std::string line = command + "\n";
  ::send(fd, line.data(), line.size(), MSG_NOSIGNAL);
  std::size_t nl;
  while ((nl = buf.find('\n')) == std::string::npos) {
    char chunk[4096];
    const ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
    if (n <= 0) return "";
    buf.append(chunk, static_cast<std::size_t>(n));
  }
  std::string reply = buf.substr(0, nl);
  buf.erase(0, nl + 1);
  return reply;
}

int connect_loopback(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<std::uint16_t>(port));
  ::inet_pton(AF_INET, "127.0.0.1", &sa.sin_addr);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0) return -1;
  return fd;
}

// The process's resident set, MiB (VmRSS of /proc/self/status).
double rss_mib() {
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return -1;
}

struct LoadRun {
  int ok = 0, busy = 0;
  std::set<long long> serials;  // as the OK replies gave them
  double rss_first_mib = 0, rss_tenth_mib = 0, rss_last_mib = 0;
  double seconds = 0;
  std::string failure;
};

// `clients` connections marking until `parts` parts are done (see the head comment).
LoadRun load_run(int port, int parts, int clients) {
  LoadRun run;
  std::mutex m;
  std::atomic<int> done{0};
  {  // the first part alone: the RSS after it is the station's working set, fonts and caches loaded
    const int fd = connect_loopback(port);
    std::string buf;
    const std::string r = ask(fd, buf, "MARK");
    ::close(fd);
    if (r.rfind("OK id=", 0) != 0) return run.failure = "first part: " + r, run;
    run.ok = 1;
    run.serials.insert(std::stoll(r.substr(r.find(" serial=") + 8)));
    done = 1;
    run.rss_first_mib = rss_mib();
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  for (int i = 0; i < clients; ++i)
    threads.emplace_back([&] {
      const int fd = connect_loopback(port);
      std::string buf;
      while (done.load() < parts) {
        const std::string r = ask(fd, buf, "MARK");
        std::lock_guard lock(m);
        if (r.rfind("OK id=", 0) == 0) {
          ++done;
          ++run.ok;
          if (run.ok == std::max(2, parts / 10)) run.rss_tenth_mib = rss_mib();
          const std::size_t at = r.find(" serial=");
          if (at == std::string::npos || !run.serials.insert(std::stoll(r.substr(at + 8))).second)
            run.failure = "a serial replied twice or missing: " + r;
        } else if (r.rfind("ERR busy ", 0) == 0) {
          ++run.busy;
          m.unlock();
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
          m.lock();
        } else {
          run.failure = "unexpected reply: " + r;
          done = parts;
        }
      }
      ::close(fd);
    });
  for (auto& t : threads) t.join();
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  run.rss_last_mib = rss_mib();
  return run;
}

// The store after a load run: one done row per OK reply, the same serials, none twice.
std::string check_store(const std::string& store, const LoadRun& run) {
  std::multiset<long long> stored;
  int rows = 0;
  for (const mark::AuditRow& r : mark::open_store(store, mark::StoreAccess::read_only)->log()) {
    if (r.mark.kind == mark::AuditKind::create) continue;
    ++rows;
    if (!r.outcome || r.outcome->outcome != mark::Outcome::done) return "row " + std::to_string(r.id) + " is not done";
    stored.insert(r.mark.serials.at("serial"));
  }
  if (rows != run.ok) return std::to_string(rows) + " rows for " + std::to_string(run.ok) + " OK replies";
  if (std::set<long long>(stored.begin(), stored.end()).size() != stored.size()) return "a serial stored twice";
  if (!std::equal(stored.begin(), stored.end(), run.serials.begin(), run.serials.end()))
    return "the stored serials are not the replied ones";
  return "";
}

// The load run on a station of its own; prints its figures, 1 when the store disagrees.
int report_load(const mark::cli::MarkJobArgs& a, int parts, int clients) {
  LoadRun run;
  {
    mark::cli::JobSource source(a);
    mark::Station station(source);
    mark::TcpServer server(station, mark::parse_listen_address("127.0.0.1:0", "--listen"), 8);
    std::atomic<bool> stop{false};
    std::thread serving([&] { server.serve([&] { return stop.load(); }); });
    run = load_run(server.port(), parts, clients);
    stop = true;
    serving.join();
  }
  const std::string wrong = run.failure.empty() ? check_store(a.store.store, run) : run.failure;
  std::printf("station_tcp: load run, %d clients, %d parts (%s)\n", clients, run.ok,
              a.virtual_time ? "virtual time" : "real time");
  std::printf("  busy replies               %d (each retried after 1 ms)\n", run.busy);
  std::printf("  marks per second           %.1f\n", (run.ok - 1) / run.seconds);
  std::printf("  RSS after the first part   %.1f MiB\n", run.rss_first_mib);
  std::printf("  RSS after a tenth of them  %.1f MiB (every thread's allocator arena in use)\n", run.rss_tenth_mib);
  std::printf("  RSS after the last part    %.1f MiB (%+.1f MiB since the tenth)\n", run.rss_last_mib,
              run.rss_last_mib - run.rss_tenth_mib);
  std::printf("  store                      %s\n", wrong.empty() ? "one done row per OK reply, no serial twice" : wrong.c_str());
  return wrong.empty() ? 0 : 1;
}

void print(const char* what, const std::vector<double>& ms, const char* note = "") {
  std::printf("  %-26s median %.3f ms  p99 %.3f ms%s\n", what, quantile(ms, 0.5), quantile(ms, 0.99), note);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("the marking station's TCP figures on loopback");
  int parts = 200;
  bool real_time = false;
  app.add_option("--parts", parts, "MARKs to send")->check(CLI::Range(2, 1'000'000));
  app.add_flag("--real-time", real_time, "drain at the scanner's clock (default: virtual time)");
  int clients = 1;
  app.add_option("--clients", clients, "concurrent clients: more than 1 is the load run")->check(CLI::Range(1, 8));
  std::string device = "sim";
  app.add_option("--device", device, "the device the station marks on")->check(CLI::IsMember({"sim", "lmc-emulated"}));
  bool http = false;
  app.add_flag("--http", http, "also POST /api/mark after each MARK, and STATUS against GET /api/status");
  CLI11_PARSE(app, argc, argv);

  const auto dir = std::filesystem::temp_directory_path() / ("station-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "serial20.json") << kSerial20Job;
  std::vector<double> rtt_ms, compile_ms, http_ms, status_ms, http_status_ms;
  mark::bench::TriggerSteps first;
  double total_s = 0;
  if (clients > 1) {
    const int code = report_load(mark::bench::serial20_args(dir, real_time, device), parts, clients);
    std::filesystem::remove_all(dir);
    return code;
  }
  {
    mark::cli::JobSource source(mark::bench::serial20_args(dir, real_time, device));
    mark::Station station(source);
    mark::TcpServer server(station, mark::parse_listen_address("127.0.0.1:0", "--listen"), 8);
    std::atomic<bool> stop{false};
    std::thread serving([&] { server.serve([&] { return stop.load(); }); });
    const int fd = connect_loopback(server.port());
    if (fd < 0) return 1;
    const mark::lmc::EmulatedBoard* board = nullptr;
    if (device == "lmc-emulated")
      board = &dynamic_cast<mark::cli::EmulatedLmcDevice&>(source.device()).emulated_board();
    std::unique_ptr<mark::HttpServer> http_server;
    std::unique_ptr<httplib::Client> client;
    if (http) {
      http_server = std::make_unique<mark::HttpServer>(station, mark::parse_listen_address("127.0.0.1:0", "--http"));
      client = std::make_unique<httplib::Client>("127.0.0.1", http_server->port());
      client->set_keep_alive(true);
      client->set_tcp_nodelay(true);
      client->set_read_timeout(std::chrono::seconds(60));
    }
    const auto t_all = std::chrono::steady_clock::now();
    std::string buf;
    for (int i = 0; i < parts; ++i) {
      auto t0 = std::chrono::steady_clock::now();
      const std::string reply = ask(fd, buf, "MARK");
      const double rtt = ms_since(t0);
      if (reply.rfind("OK ", 0) != 0) {
        std::fprintf(stderr, "station_tcp: part %d: %s\n", i + 1, reply.c_str());
        return 1;
      }
      const auto last = station.status().last;
      const auto& r = last->objects.at(0).result;
      rtt_ms.push_back(rtt);
      const auto first_sample = board ? mark::bench::board_first_sample(*board, t0) : r.drain.first_write;
      if (!first_sample) {
        std::fprintf(stderr, "station_tcp: part %d: no ExecuteList reached the board\n", i + 1);
        return 1;
      }
      first.add(t0, *last, *first_sample);
      compile_ms.push_back(1e3 * r.compile_time_s);
      if (!client) continue;
      t0 = std::chrono::steady_clock::now();
      const auto h = client->Post("/api/mark");
      http_ms.push_back(ms_since(t0));
      if (!h || h->status != 200) {
        std::fprintf(stderr, "station_tcp: HTTP part %d: %s\n", i + 1,
                     h ? h->body.c_str() : httplib::to_string(h.error()).c_str());
        return 1;
      }
    }
    total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_all).count();
    for (int i = 0; client && i < parts; ++i) {
      auto t0 = std::chrono::steady_clock::now();
      if (ask(fd, buf, "STATUS").rfind("OK ", 0) != 0) return 1;
      status_ms.push_back(ms_since(t0));
      t0 = std::chrono::steady_clock::now();
      const auto h = client->Get("/api/status");
      http_status_ms.push_back(ms_since(t0));
      if (!h || h->status != 200) return 1;
    }
    ::close(fd);
    stop = true;
    serving.join();
    if (http_server) http_server->stop();
  }
  std::filesystem::remove_all(dir);
  std::printf("station_tcp: %d parts (%s) on %s, 20-character serial \"SN 00000000000000001\"\n", parts,
              real_time ? "real time" : "virtual time", device.c_str());
  print("MARK round trip", rtt_ms);
  first.print("the client's send to the device's first block");
  print("first block in memory", compile_ms, "  (JobResult compile_time_s: the compiled job to its first block in the line memory)");
  std::printf("  marks per second           %.1f%s\n", (http ? 2 : 1) * parts / total_s, http ? " (TCP and HTTP)" : "");
  if (!http) return 0;
  print("POST /api/mark round trip", http_ms, "  (alternating with MARK)");
  std::printf("  HTTP - TCP medians         %.3f ms\n", quantile(http_ms, 0.5) - quantile(rtt_ms, 0.5));
  print("STATUS round trip", status_ms, "  (no part: the adapters alone)");
  print("GET /api/status round trip", http_status_ms);
  return 0;
}
