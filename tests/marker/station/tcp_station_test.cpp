// `marker serve`'s TCP line protocol end to end, in process: a job file on the simulated
// scanner with a real SQLite serial store (JobSource → PartRunner), the Station, the TcpServer
// on a free loopback port, and real socket clients. What is checked against something the
// station did not compute: the audit rows the store kept (read back through a second open of
// the store after the station closed it) and PREVIEW's rendering of the next part.
#include <gtest/gtest.h>

#include <mutex>
#include <set>

#include "base/error.hpp"
#include "marker/station/station_commands.hpp"
#include "tests/marker/station/served_station.hpp"
#include "tests/marker/production/plates_job.hpp"

namespace mark {
namespace {

using test::Served;
using Client = test::LineClient;

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
  test::expect_one_part(s.close(), 2, 41, Outcome::done, "SN 000041 LOT A17");
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
  test::expect_rows_are_the_replies(s.close(), replied);
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
  test::expect_one_part(s.close(), 2, 41, Outcome::aborted);
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
    EXPECT_EQ(std::string(e.what()).rfind(
              "--listen 0.0.0.0:5555: only loopback addresses (127.0.0.0/8) for a station without a token: give --token "
              "FILE to listen beyond loopback", 0), 0u) << e.what();
  }
  EXPECT_EQ(parse_listen_address("0.0.0.0:5555", "--listen", true).host, "0.0.0.0");  // with --token
  EXPECT_THROW(parse_listen_address("127.0.0.1:70000", "--listen"), InputError);
  EXPECT_THROW(parse_listen_address("0.0.0.0:70000", "--listen", true), InputError);
  EXPECT_THROW(parse_listen_address("127.0.0.1", "--listen"), InputError);
}

}  // namespace
}  // namespace mark

namespace mark {
namespace {

// PREVIEW on a job with a data list shows the row the next part takes: the first untaken one,
// after a part took row 1; once every row is taken it says the next part would be refused.
TEST(StationTcp, PreviewShowsTheDataListRowTheNextPartTakes) {
  const auto dir = test::fresh_store_dir("station-data");
  test::write_plates_list(dir);
  {
    const cli::MarkJobArgs a = test::station_job_args(dir, "plates.json", test::kPlatesJob,
                                                      (dir / "plates.sqlite").string(), "sim");
    cli::JobSource source(a);
    Station station(source);
    const auto preview = [&] { return station_command(station, "PREVIEW"); };
    EXPECT_NE(preview().find("VIN-A 000041"), std::string::npos) << preview();
    ASSERT_EQ(station_command(station, "MARK").rfind("OK id=", 0), 0u);
    EXPECT_NE(preview().find("VIN-B 000042"), std::string::npos) << preview();
    ASSERT_EQ(station_command(station, "MARK").rfind("OK id=", 0), 0u);
    EXPECT_NE(preview().find("data list plates.csv: every row was taken by an earlier part (2 rows in the file)"),
              std::string::npos)
        << preview();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mark
