#pragma once
// `marker serve` in process for the station's interface suites (StationTcp, StationHttp): a job
// file on the simulated scanner with a real SQLite serial store (JobSource → PartRunner), the
// Station, the TcpServer, the HttpServer and the ModbusServer on free loopback ports, and a
// line-protocol client.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "marker/cli/serve_source.hpp"
#include "marker/station/http_server.hpp"
#include "marker/station/modbus_server.hpp"
#include "marker/station/tcp_server.hpp"
#include "marker/store/open_store.hpp"
#include "tests/marker/store/store_test_support.hpp"

namespace mark::test {

inline constexpr const char* kStationJob = R"({
  "format": "marker-job/1",
  "head": "SL10",
  "time_zone": "UTC",
  "variables": {"lot": "A00"},
  "counters": {"serial": {"start": 41, "width": 6}},
  "pens": {"fine": {"speed_mm_s": 800, "power_pct": 100, "frequency_khz": 40}},
  "objects": [
    {"name": "serial", "pen": "fine", "template": "SN {serial} LOT {var:lot}", "height_mm": 3, "x_mm": -20, "y_mm": 0}
  ]
})";

class LineClient {
 public:
  explicit LineClient(int port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in sa{};
    sa.sin_family = AF_INET;
    sa.sin_port = htons(static_cast<std::uint16_t>(port));
    ::inet_pton(AF_INET, "127.0.0.1", &sa.sin_addr);
    if (::connect(fd_, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0) throw std::runtime_error("connect");
  }
  ~LineClient() { ::close(fd_); }
  void send_raw(const std::string& s) { ASSERT_EQ(::send(fd_, s.data(), s.size(), MSG_NOSIGNAL), static_cast<ssize_t>(s.size())); }
  // One reply line; "" when the server closed the connection.
  std::string line() {
    for (;;) {
      const std::size_t nl = buf_.find('\n');
      if (nl != std::string::npos) {
        std::string l = buf_.substr(0, nl);
        buf_.erase(0, nl + 1);
        return l;
      }
      char chunk[4096];
      const ssize_t n = ::recv(fd_, chunk, sizeof chunk, 0);
      if (n <= 0) return "";
      buf_.append(chunk, static_cast<std::size_t>(n));
    }
  }
  std::string ask(const std::string& command) {
    send_raw(command + "\n");
    return line();
  }

 private:
  int fd_ = -1;
  std::string buf_;
};

// The job source of an in-process station: `job_text` written to DIR/NAME, the serial store
// beside it, station s1 creating its counters on first use, in virtual time unless told.
inline cli::MarkJobArgs station_job_args(const std::filesystem::path& dir, const std::string& name,
                                         const std::string& job_text, const std::string& store_path,
                                         const std::string& device, bool virtual_time = true) {
  const std::string job = (dir / name).string();
  std::ofstream(job) << job_text;
  cli::MarkJobArgs a;
  a.job = job;
  a.store.store = store_path;
  a.station = "s1";
  a.create_counters = true;
  a.virtual_time = virtual_time;
  a.device = device;
  return a;
}

struct Served {
  std::filesystem::path dir = fresh_store_dir("station");
  std::string store_path = (dir / "line.serials.sqlite").string();
  std::unique_ptr<cli::JobSource> source;
  std::unique_ptr<Station> station;
  std::unique_ptr<TcpServer> server;
  std::unique_ptr<HttpServer> http;
  std::unique_ptr<ModbusServer> modbus;
  std::atomic<bool> stop{false};
  std::thread thread;

  // `inject`: marker mark's --inject (fault@N: every part fails at sample N). `token`: marker
  // serve --token's (empty: none), for the TCP and HTTP servers.
  explicit Served(bool virtual_time = true, int max_connections = 8, const std::string& inject = {},
                  const std::string& token = {}) {
    cli::MarkJobArgs a = station_job_args(dir, "line.json", kStationJob, store_path, "sim", virtual_time);
    a.inject = inject;
    source = std::make_unique<cli::JobSource>(a);
    station = std::make_unique<Station>(*source);
    server = std::make_unique<TcpServer>(*station, parse_listen_address("127.0.0.1:0", "--listen"), max_connections,
                                         nullptr, token);
    http = std::make_unique<HttpServer>(*station, parse_listen_address("127.0.0.1:0", "--http"), nullptr, token);
    modbus = std::make_unique<ModbusServer>(*station, parse_listen_address("127.0.0.1:0", "--modbus"),
                                            std::vector<AllowedNet>{}, max_connections);
    thread = std::thread([this] { server->serve([this] { return stop.load(); }); });
  }
  int port() const { return server->port(); }
  int http_port() const { return http->port(); }
  int modbus_port() const { return modbus->port(); }
  // Stops everything and gives the parts' audit rows, read back from the store file.
  std::vector<AuditRow> close() {
    stop = true;
    if (thread.joinable()) thread.join();
    modbus.reset();
    server.reset();
    http.reset();
    station.reset();
    source.reset();
    auto store = open_store(store_path, StoreAccess::existing);
    std::vector<AuditRow> rows;
    for (AuditRow& r : store->log())
      if (r.mark.kind != AuditKind::create) rows.push_back(std::move(r));
    return rows;
  }
  ~Served() {
    if (thread.joinable()) close();
    std::filesystem::remove_all(dir);
  }
};

// The store's rows are one part, `id`, that ended `outcome` with serial `serial` (and `text`
// when given).
inline void expect_one_part(const std::vector<AuditRow>& rows, std::int64_t id, std::int64_t serial, Outcome outcome,
                            const std::string& text = {}) {
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].id, id);
  EXPECT_EQ(rows[0].mark.serials.at("serial"), serial);
  if (!text.empty()) {
    EXPECT_EQ(rows[0].text(), text);
  }
  ASSERT_TRUE(rows[0].outcome);
  EXPECT_EQ(rows[0].outcome->outcome, outcome);
}

// The store holds exactly one done row per part a client was told was done, with the serials
// the clients were told, consecutive from the job's start (a refused trigger consumed nothing).
inline void expect_rows_are_the_replies(const std::vector<AuditRow>& rows, const std::set<std::int64_t>& replied) {
  ASSERT_EQ(rows.size(), replied.size());
  std::set<std::int64_t> stored;
  for (const AuditRow& r : rows) {
    ASSERT_TRUE(r.outcome);
    EXPECT_EQ(r.outcome->outcome, Outcome::done);
    stored.insert(r.mark.serials.at("serial"));
  }
  EXPECT_EQ(stored, replied);
  ASSERT_FALSE(stored.empty());
  EXPECT_EQ(*stored.begin(), 41);
  EXPECT_EQ(*stored.rbegin(), 41 + static_cast<std::int64_t>(stored.size()) - 1);
}

}  // namespace mark::test
