// `marker serve`'s TCP line protocol end to end, in process: a job file on the simulated
// scanner with a real SQLite serial store (JobSource → PartRunner), the Station, the TcpServer
// on a free loopback port, and real socket clients. What is checked against something the
// station did not compute: the audit rows the store kept (read back through a second open of
// the store after the station closed it) and PREVIEW's rendering of the next part.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <set>
#include <thread>

#include "base/error.hpp"
#include "marker/cli/serve_source.hpp"
#include "marker/station/tcp_server.hpp"
#include "marker/store/open_store.hpp"
#include "tests/marker/store/store_test_support.hpp"

namespace mark {
namespace {

constexpr const char* kJob = R"({
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

class Client {
 public:
  explicit Client(int port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in sa{};
    sa.sin_family = AF_INET;
    sa.sin_port = htons(static_cast<std::uint16_t>(port));
    ::inet_pton(AF_INET, "127.0.0.1", &sa.sin_addr);
    if (::connect(fd_, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0) throw std::runtime_error("connect");
  }
  ~Client() { ::close(fd_); }
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

struct Served {
  std::filesystem::path dir = test::fresh_store_dir("station-tcp");
  std::string store_path = (dir / "line.serials.sqlite").string();
  std::unique_ptr<cli::JobSource> source;
  std::unique_ptr<Station> station;
  std::unique_ptr<TcpServer> server;
  std::atomic<bool> stop{false};
  std::thread thread;

  explicit Served(bool virtual_time = true, int max_connections = 8) {
    const std::string job = (dir / "line.json").string();
    std::ofstream(job) << kJob;
    cli::MarkJobArgs a;
    a.job = job;
    a.store.store = store_path;
    a.station = "s1";
    a.create_counters = true;
    a.virtual_time = virtual_time;
    a.device = "sim";
    source = std::make_unique<cli::JobSource>(a);
    station = std::make_unique<Station>(*source);
    server = std::make_unique<TcpServer>(*station, parse_listen_address("127.0.0.1:0", "--listen"), max_connections);
    thread = std::thread([this] { server->serve([this] { return stop.load(); }); });
  }
  int port() const { return server->port(); }
  // Stops everything and gives the parts' audit rows, read back from the store file.
  std::vector<AuditRow> close() {
    stop = true;
    if (thread.joinable()) thread.join();
    server.reset();
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

TEST(StationTcp, MarkRepliesWithRenderedTextSerialAndOutcome) {
  Served s;
  Client c(s.port());
  EXPECT_EQ(c.ask("PREVIEW"), "OK serial=41 text=\"SN 000041 LOT A00\"");
  EXPECT_EQ(c.ask("SET lot A17"), "OK lot=A17");
  EXPECT_EQ(c.ask("SERIAL serial"), "OK serial=41");
  const std::string r = c.ask("MARK");
  EXPECT_EQ(r.substr(0, 58), "OK id=2 outcome=done serial=41 text=\"SN 000041 LOT A17\" ma") << r;
  EXPECT_EQ(c.ask("SERIAL serial"), "OK serial=42");
  EXPECT_EQ(c.ask("STATUS").substr(0, 17), "OK state=idle job");
  const auto rows = s.close();
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].id, 2);
  EXPECT_EQ(rows[0].mark.serials.at("serial"), 41);
  EXPECT_EQ(rows[0].text(), "SN 000041 LOT A17");
  ASSERT_TRUE(rows[0].outcome);
  EXPECT_EQ(rows[0].outcome->outcome, Outcome::done);
}

// Four clients trigger at once, many times: one part at a time, every other trigger `busy`;
// the store then holds exactly one row per OK and no serial twice.
TEST(StationTcp, FourClientsOneMarkAtATimeNoSerialRepeated) {
  Served s;
  constexpr int kClients = 4, kEach = 15;
  std::atomic<int> ok{0}, busy{0}, other{0};
  std::set<std::int64_t> replied;
  std::mutex m;
  std::vector<std::thread> clients;
  for (int i = 0; i < kClients; ++i)
    clients.emplace_back([&] {
      Client c(s.port());
      for (int k = 0; k < kEach; ++k) {
        const std::string r = c.ask("MARK");
        if (r.rfind("OK id=", 0) == 0) {
          ++ok;
          const std::size_t at = r.find(" serial=");
          std::lock_guard l(m);
          replied.insert(std::stoll(r.substr(at + 8)));
        } else if (r.rfind("ERR busy ", 0) == 0) {
          ++busy;
        } else {
          ++other;
          ADD_FAILURE() << r;
        }
      }
    });
  for (auto& t : clients) t.join();
  EXPECT_EQ(ok + busy, kClients * kEach);
  EXPECT_EQ(other.load(), 0);
  ASSERT_GT(ok.load(), 0);
  EXPECT_EQ(replied.size(), static_cast<std::size_t>(ok.load()));  // no serial replied twice
  const auto rows = s.close();
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(ok.load()));
  std::set<std::int64_t> stored;
  for (const AuditRow& r : rows) {
    ASSERT_TRUE(r.outcome);
    EXPECT_EQ(r.outcome->outcome, Outcome::done);
    stored.insert(r.mark.serials.at("serial"));
  }
  EXPECT_EQ(stored, replied);
  // Consecutive from the start: nothing consumed by a refused trigger.
  EXPECT_EQ(*stored.begin(), 41);
  EXPECT_EQ(*stored.rbegin(), 41 + ok.load() - 1);
}

// In real time a part takes long enough to abort it: the laser goes off, the part is recorded
// aborted and its number is void; the next part takes the next number.
TEST(StationTcp, AbortMidMarkRecordsThePartAborted) {
  Served s(false);
  Client c(s.port());
  ASSERT_EQ(c.ask("MARK ASYNC"), "OK started");
  EXPECT_EQ(c.ask("MARK").substr(0, 9), "ERR busy ");
  EXPECT_EQ(c.ask("ABORT"), "OK laser_off state_was=marking");
  s.station->wait_idle();
  const std::string st = c.ask("STATUS");
  EXPECT_NE(st.find("state=idle"), std::string::npos) << st;
  EXPECT_NE(st.find("last_outcome=aborted"), std::string::npos) << st;
  const auto last = s.station->status().last;
  ASSERT_TRUE(last);
  ASSERT_FALSE(last->objects.empty());
  EXPECT_EQ(last->objects[0].result.outcome, JobOutcome::aborted);
  EXPECT_EQ(c.ask("SERIAL serial"), "OK serial=42");
  const auto rows = s.close();
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_TRUE(rows[0].outcome);
  EXPECT_EQ(rows[0].outcome->outcome, Outcome::aborted);
  EXPECT_EQ(rows[0].mark.serials.at("serial"), 41);
}

TEST(StationTcp, LimitsAnswerErrAndChangeNothing) {
  Served s(true, 2);
  Client a(s.port()), b(s.port());
  EXPECT_EQ(a.ask("STATUS").substr(0, 13), "OK state=idle");
  EXPECT_EQ(b.ask("STATUS").substr(0, 13), "OK state=idle");
  Client third(s.port());
  EXPECT_EQ(third.line(), "ERR toomany the station takes at most 2 connections at a time; close one first");
  EXPECT_EQ(third.line(), "");  // closed
  // A line over 4 KiB: one ERR, the rest of it ignored, the connection still answers.
  a.send_raw(std::string(5000, 'M') + "\n");
  EXPECT_EQ(a.line().substr(0, 11), "ERR toolong");
  EXPECT_EQ(a.ask("SERIAL serial"), "OK serial=41");
  EXPECT_EQ(a.ask("SET size 3").substr(0, 12), "ERR refused ");
  EXPECT_EQ(s.close().size(), 0u);
}

TEST(StationTcp, ListenRefusesNonLoopback) {
  EXPECT_EQ(parse_listen_address("localhost:0", "--listen").host, "127.0.0.1");
  EXPECT_EQ(parse_listen_address(":7000", "--listen").port, 7000);
  try {
    parse_listen_address("0.0.0.0:5555", "--listen");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 64), "--listen 0.0.0.0:5555: only loopback addresses (127.0.0.0/8) for");
  }
  EXPECT_THROW(parse_listen_address("127.0.0.1:70000", "--listen"), InputError);
  EXPECT_THROW(parse_listen_address("127.0.0.1", "--listen"), InputError);
}

}  // namespace
}  // namespace mark
