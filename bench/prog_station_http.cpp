// The station's HTTP round trip against its TCP line protocol, in one run on loopback (issue 22):
// the 20-character serial job of station_tcp ("SN " + 17 digits) on the simulated scanner with a
// SQLite store in a temporary folder, `marker serve`'s parts (JobSource → Station) behind both
// a TcpServer and an HttpServer in process; one TCP client sending MARK and one httplib::Client
// sending POST /api/mark (keep-alive), alternately, so both see the same store and machine load.
//
//   station_http [--parts N] [--real-time]
//
// Prints the median and p99 round trip of each (the client's send to the whole reply) and
// their difference: what HTTP + JSON (the part as `mark --job --json` prints it) costs over
// the line protocol; then STATUS against GET /api/status, the adapters without a part.
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
#include <thread>
#include <vector>

#include "marker/cli/serve_source.hpp"
#include "marker/station/http_server.hpp"
#include "marker/station/tcp_server.hpp"
// Last: it brings <resolv.h>, whose `_res` macro breaks Eigen's headers included after it.
#include <httplib.h>

namespace {

constexpr const char* kJob = R"({
  "format": "marker-job/1", "head": "SL10", "time_zone": "UTC",
  "counters": {"serial": {"start": 1, "width": 17}},
  "pens": {"fine": {"speed_mm_s": 2000, "power_pct": 100, "frequency_khz": 40}},
  "objects": [{"name": "serial", "pen": "fine", "template": "SN {serial}", "height_mm": 2, "x_mm": -30, "y_mm": 0}]
})";

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("the marking station's HTTP and TCP MARK round trips on loopback");
  int parts = 200;
  bool real_time = false;
  app.add_option("--parts", parts, "parts per interface")->check(CLI::Range(2, 1'000'000));
  app.add_flag("--real-time", real_time, "drain at the scanner's clock (default: virtual time)");
  CLI11_PARSE(app, argc, argv);

  const auto dir = std::filesystem::temp_directory_path() / ("station-http-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "serial20.json") << kJob;
  std::vector<double> tcp_ms, http_ms, tcp_status_ms, http_status_ms;
  int status = 0;
  {
    mark::cli::MarkJobArgs a;
    a.job = (dir / "serial20.json").string();
    a.store.store = (dir / "bench.sqlite").string();
    a.station = "bench";
    a.create_counters = true;
    a.virtual_time = !real_time;
    a.device = "sim";
    mark::cli::JobSource source(a);
    mark::Station station(source);
    mark::TcpServer tcp(station, mark::parse_listen_address("127.0.0.1:0", "--listen"), 8);
    mark::HttpServer http(station, mark::parse_listen_address("127.0.0.1:0", "--http"));
    std::atomic<bool> stop{false};
    std::thread serving([&] { tcp.serve([&] { return stop.load(); }); });

    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in sa{};
    sa.sin_family = AF_INET;
    sa.sin_port = htons(static_cast<std::uint16_t>(tcp.port()));
    ::inet_pton(AF_INET, "127.0.0.1", &sa.sin_addr);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0) return 1;
    httplib::Client client("127.0.0.1", http.port());
    client.set_keep_alive(true);
    client.set_tcp_nodelay(true);
    client.set_read_timeout(std::chrono::seconds(60));
    std::string buf;
    for (int i = 0; i < parts && status == 0; ++i) {
      auto t0 = std::chrono::steady_clock::now();
      ::send(fd, "MARK\n", 5, MSG_NOSIGNAL);
      std::size_t nl;
      while ((nl = buf.find('\n')) == std::string::npos) {
        char chunk[4096];
        const ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
        if (n <= 0) return 1;
        buf.append(chunk, static_cast<std::size_t>(n));
      }
      tcp_ms.push_back(ms_since(t0));
      const std::string reply = buf.substr(0, nl);
      buf.erase(0, nl + 1);
      if (reply.rfind("OK ", 0) != 0) {
        std::fprintf(stderr, "station_http: TCP part %d: %s\n", i + 1, reply.c_str());
        status = 1;
      }
      t0 = std::chrono::steady_clock::now();
      const auto r = client.Post("/api/mark");
      http_ms.push_back(ms_since(t0));
      if (!r || r->status != 200) {
        std::fprintf(stderr, "station_http: HTTP part %d: %s\n", i + 1,
                     r ? r->body.c_str() : httplib::to_string(r.error()).c_str());
        status = 1;
      }
    }
    // The adapters alone, without a part: STATUS against GET /api/status.
    for (int i = 0; i < parts && status == 0; ++i) {
      auto t0 = std::chrono::steady_clock::now();
      ::send(fd, "STATUS\n", 7, MSG_NOSIGNAL);
      std::size_t nl;
      while ((nl = buf.find('\n')) == std::string::npos) {
        char chunk[4096];
        const ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
        if (n <= 0) return 1;
        buf.append(chunk, static_cast<std::size_t>(n));
      }
      tcp_status_ms.push_back(ms_since(t0));
      buf.erase(0, nl + 1);
      t0 = std::chrono::steady_clock::now();
      const auto r = client.Get("/api/status");
      http_status_ms.push_back(ms_since(t0));
      if (!r || r->status != 200) status = 1;
    }
    ::close(fd);
    stop = true;
    serving.join();
    http.stop();
  }
  std::filesystem::remove_all(dir);
  if (status != 0) return status;
  std::printf("station_http: %d parts per interface, alternately (%s), 20-character serial \"SN 00000000000000001\"\n",
              parts, real_time ? "real time" : "virtual time");
  std::printf("  TCP  MARK            round trip  median %.3f ms  p99 %.3f ms\n", quantile(tcp_ms, 0.5),
              quantile(tcp_ms, 0.99));
  std::printf("  HTTP POST /api/mark  round trip  median %.3f ms  p99 %.3f ms\n", quantile(http_ms, 0.5),
              quantile(http_ms, 0.99));
  std::printf("  HTTP − TCP medians   %.3f ms\n", quantile(http_ms, 0.5) - quantile(tcp_ms, 0.5));
  std::printf("  TCP  STATUS          round trip  median %.3f ms  p99 %.3f ms  (no part: the adapters alone)\n",
              quantile(tcp_status_ms, 0.5), quantile(tcp_status_ms, 0.99));
  std::printf("  HTTP GET /api/status round trip  median %.3f ms  p99 %.3f ms\n", quantile(http_status_ms, 0.5),
              quantile(http_status_ms, 0.99));
  return 0;
}
