// `marker serve`'s HTTP + JSON interface end to end, in process: the job on the simulated
// scanner with a real SQLite store, the Station, its TcpServer and HttpServer on free loopback
// ports, and a real HTTP client (httplib::Client) — a different implementation of the HTTP side
// than the server's parser only in part (same library), so the replies are also checked against
// what the station did not compute: the audit rows the store kept, read back through a second
// open of the store after the station closed it, and the TCP line protocol's view.
#include <gtest/gtest.h>

#include <barrier>
#include <chrono>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>

#include "base/error.hpp"
#include "tests/marker/station/served_station.hpp"
// Last: it brings <resolv.h>, whose `_res` macro breaks Eigen's headers included after it.
#include <httplib.h>

namespace mark {
namespace {

using nlohmann::json;
using test::Served;

struct Reply {
  int status = 0;
  json body;
};

Reply call(httplib::Client& c, const std::string& method, const std::string& path, const std::string& body = {}) {
  httplib::Result r = method == "GET"    ? c.Get(path)
                      : method == "PUT"  ? c.Put(path, body, "text/plain")
                      : body.empty()     ? c.Post(path)
                                         : c.Post(path, body, "application/json");
  if (!r) {
    ADD_FAILURE() << method << " " << path << ": " << httplib::to_string(r.error());
    return {};
  }
  Reply out{r->status, json::parse(r->body, nullptr, false)};
  EXPECT_FALSE(out.body.is_discarded()) << method << " " << path << ": not JSON: " << r->body.substr(0, 200);
  return out;
}

std::unique_ptr<httplib::Client> client(const Served& s) {
  auto c = std::make_unique<httplib::Client>("127.0.0.1", s.http_port());
  c->set_read_timeout(std::chrono::seconds(30));
  return c;
}

TEST(StationHttp, StatusPreviewVarsAndMarkReturnThePartWithSerials) {
  Served s;
  auto c = client(s);
  Reply st = call(*c, "GET", "/api/status");
  EXPECT_EQ(st.status, 200);
  EXPECT_EQ(st.body["state"], "idle");
  EXPECT_EQ(st.body["parts"], 0);
  EXPECT_TRUE(st.body["last"].is_null());

  Reply p = call(*c, "GET", "/api/preview");
  EXPECT_EQ(p.body["text"], "SN 000041 LOT A00");
  EXPECT_EQ(p.body["serials"]["serial"], 41);
  Reply v = call(*c, "PUT", "/api/vars/lot", "A17\n");  // the line's end is not the value's
  EXPECT_EQ(v.status, 200);
  EXPECT_EQ(v.body["value"], "A17");
  EXPECT_EQ(call(*c, "GET", "/api/preview").body["text"], "SN 000041 LOT A17");
  EXPECT_EQ(call(*c, "GET", "/api/serial/serial").body["next"], 41);

  Reply m = call(*c, "POST", "/api/mark");
  EXPECT_EQ(m.status, 200);
  EXPECT_EQ(m.body["outcome"], "done");
  EXPECT_EQ(m.body["mark_id"], 2);
  EXPECT_EQ(m.body["serials"]["serial"], 41);
  EXPECT_EQ(m.body["text"], "SN 000041 LOT A17");
  EXPECT_GT(m.body["mark_time_s"].get<double>(), 0.0);
  EXPECT_EQ(call(*c, "GET", "/api/serial/serial").body["next"], 42);
  st = call(*c, "GET", "/api/status");
  EXPECT_EQ(st.body["parts"], 1);
  EXPECT_EQ(st.body["outcomes"]["done"], 1);
  EXPECT_EQ(st.body["last"]["mark_id"], 2);

  // The log as `marker log --json` gives it: the counter's creation, then the part.
  Reply log = call(*c, "GET", "/api/log?limit=1");
  ASSERT_EQ(log.status, 200);
  ASSERT_EQ(log.body.size(), 1u);
  EXPECT_EQ(log.body[0]["id"], 2);
  EXPECT_EQ(log.body[0]["text"], "SN 000041 LOT A17");
  EXPECT_EQ(log.body[0]["outcome"], "done");
  EXPECT_EQ(call(*c, "GET", "/api/log").body.size(), 2u);

  test::expect_one_part(s.close(), 2, 41, Outcome::done, "SN 000041 LOT A17");
}

// Four clients POST /api/mark at the same instant, round after round: one part at a time, every
// other trigger 409 busy; the store holds exactly one row per 200 and no serial twice.
TEST(StationHttp, FourConcurrentMarksOneMarksTheRestBusy) {
  Served s;
  constexpr int kClients = 4, kRounds = 12;
  std::atomic<int> ok{0}, busy{0};
  std::set<std::int64_t> replied;
  std::mutex m;
  std::barrier start(kClients);
  std::vector<std::thread> clients;
  for (int i = 0; i < kClients; ++i)
    clients.emplace_back([&] {
      auto c = client(s);
      for (int k = 0; k < kRounds; ++k) {
        start.arrive_and_wait();
        const Reply r = call(*c, "POST", "/api/mark");
        if (r.status == 200) {
          ++ok;
          std::lock_guard l(m);
          EXPECT_TRUE(replied.insert(r.body["serials"]["serial"].get<std::int64_t>()).second);
        } else if (r.status == 409) {
          ++busy;
          EXPECT_EQ(r.body["code"], "busy");
          EXPECT_FALSE(r.body["error"].get<std::string>().empty());
        } else {
          ADD_FAILURE() << r.status << " " << r.body.dump();
        }
        start.arrive_and_wait();  // the round's part ended before the next round
      }
    });
  for (auto& t : clients) t.join();
  EXPECT_EQ(ok + busy, kClients * kRounds);
  EXPECT_GE(ok.load(), kRounds);  // at least one part per round
  EXPECT_GT(busy.load(), 0);
  EXPECT_EQ(replied.size(), static_cast<std::size_t>(ok.load()));
  test::expect_rows_are_the_replies(s.close(), replied);
}

// In real time a part lasts long enough to abort it from a second client: the waiting POST gets
// 409 with the part (outcome aborted, laser off), the store has it aborted, its number void.
TEST(StationHttp, AbortMidMarkRecordsThePartAborted) {
  Served s(false);
  Reply marked;
  std::thread marker([&] {
    auto c = client(s);
    marked = call(*c, "POST", "/api/mark");
  });
  auto c = client(s);
  while (call(*c, "GET", "/api/status").body["state"] != "marking")
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  Reply a = call(*c, "POST", "/api/abort");
  EXPECT_EQ(a.status, 200);
  EXPECT_EQ(a.body["laser_off"], true);
  EXPECT_EQ(a.body["state_was"], "marking");
  marker.join();
  EXPECT_EQ(marked.status, 409);
  EXPECT_EQ(marked.body["outcome"], "aborted");
  EXPECT_EQ(marked.body["serials"]["serial"], 41);
  EXPECT_NE(marked.body["error"].get<std::string>().find("laser off"), std::string::npos) << marked.body["error"];
  const auto last = s.station->status().last;
  ASSERT_TRUE(last);
  ASSERT_FALSE(last->objects.empty());
  EXPECT_EQ(last->objects[0].result.outcome, JobOutcome::aborted);
  EXPECT_EQ(call(*c, "GET", "/api/status").body["state"], "idle");
  EXPECT_EQ(call(*c, "GET", "/api/serial/serial").body["next"], 42);
  test::expect_one_part(s.close(), 2, 41, Outcome::aborted);
}

// The event stream: `marking`, then the part, then `idle`, one `data:` JSON each, and the
// stream ends cleanly (a complete chunked response) when the server stops.
TEST(StationHttp, EventStreamTellsMarkingThePartAndIdleAndEndsOnStop) {
  Served s;
  std::mutex m;
  std::condition_variable got;
  std::string received;
  httplib::Result result{nullptr, httplib::Error::Unknown};
  std::thread listener([&] {
    httplib::Client c("127.0.0.1", s.http_port());
    c.set_read_timeout(std::chrono::seconds(30));
    result = c.Get("/api/events", [&](const char* data, std::size_t n) {
      std::lock_guard l(m);
      received.append(data, n);
      got.notify_all();
      return true;
    });
  });
  const auto wait_for = [&](const std::string& what) {
    std::unique_lock l(m);
    return got.wait_for(l, std::chrono::seconds(20), [&] { return received.find(what) != std::string::npos; });
  };
  ASSERT_TRUE(wait_for(": station events\n\n"));  // subscribed
  auto c = client(s);
  ASSERT_EQ(call(*c, "POST", "/api/mark").status, 200);
  ASSERT_TRUE(wait_for(R"(data: {"event":"state","state":"idle"})"));
  std::vector<json> events;
  {
    std::lock_guard l(m);
    for (std::size_t at = received.find("data: "); at != std::string::npos; at = received.find("data: ", at + 1)) {
      const std::size_t end = received.find("\n\n", at);
      ASSERT_NE(end, std::string::npos);
      events.push_back(json::parse(received.substr(at + 6, end - at - 6)));
    }
  }
  ASSERT_EQ(events.size(), 3u) << received;
  EXPECT_EQ(events[0], json({{"event", "state"}, {"state", "marking"}}));
  EXPECT_EQ(events[1]["event"], "part");
  EXPECT_EQ(events[1]["part"]["serials"]["serial"], 41);
  EXPECT_EQ(events[1]["part"]["text"], "SN 000041 LOT A00");
  EXPECT_EQ(events[1]["part"]["outcome"], "done");
  EXPECT_EQ(events[2], json({{"event", "state"}, {"state", "idle"}}));
  s.http->stop();
  listener.join();
  ASSERT_TRUE(result) << httplib::to_string(result.error());
  EXPECT_EQ(result->status, 200);
  EXPECT_EQ(result->get_header_value("Content-Type"), "text/event-stream");
}

// Both interfaces are adapters of one station: a part started over TCP is `marking` over HTTP,
// refuses an HTTP trigger, is aborted over HTTP and reported the same way over TCP.
TEST(StationHttp, TcpAndHttpClientsSeeTheSameStation) {
  Served s(false);
  test::LineClient tcp(s.port());
  auto c = client(s);
  ASSERT_EQ(tcp.ask("MARK ASYNC"), "OK started");
  EXPECT_EQ(call(*c, "GET", "/api/status").body["state"], "marking");
  EXPECT_EQ(call(*c, "POST", "/api/mark").status, 409);
  EXPECT_EQ(call(*c, "PUT", "/api/vars/lot", "B02").status, 409);
  EXPECT_EQ(call(*c, "POST", "/api/abort").body["state_was"], "marking");
  s.station->wait_idle();
  const std::string st = tcp.ask("STATUS");
  EXPECT_NE(st.find("state=idle"), std::string::npos) << st;
  EXPECT_NE(st.find("last_id=2 last_outcome=aborted"), std::string::npos) << st;
  const Reply hs = call(*c, "GET", "/api/status");
  EXPECT_EQ(hs.body["last"]["mark_id"], 2);
  EXPECT_EQ(hs.body["last"]["outcome"], "aborted");
  EXPECT_EQ(hs.body["outcomes"]["aborted"], 1);
  // A variable set over HTTP is the one TCP's PREVIEW renders, and the reverse.
  EXPECT_EQ(call(*c, "PUT", "/api/vars/lot", "B02").status, 200);
  EXPECT_EQ(tcp.ask("PREVIEW"), "OK serial=42 text=\"SN 000042 LOT B02\"");
  EXPECT_EQ(tcp.ask("SET lot C03"), "OK lot=C03");
  EXPECT_EQ(call(*c, "GET", "/api/preview").body["text"], "SN 000042 LOT C03");
  EXPECT_EQ(s.close().size(), 1u);
}

// Bad requests: a clear 4xx with {"error": …}; the station and the store unchanged.
TEST(StationHttp, BadRequestsAnswer4xxJsonAndChangeNothing) {
  Served s;
  auto c = client(s);
  const auto expect_error = [&](const std::string& method, const std::string& path, const std::string& body,
                                int status, const std::string& starts) {
    const Reply r = call(*c, method, path, body);
    EXPECT_EQ(r.status, status) << method << " " << path;
    ASSERT_TRUE(r.body.contains("error")) << r.body.dump();
    EXPECT_EQ(r.body["error"].get<std::string>().substr(0, starts.size()), starts) << r.body.dump();
  };
  expect_error("GET", "/api/nothing", "", 404, "no endpoint GET /api/nothing; endpoints: GET /api/status");
  expect_error("GET", "/api/mark", "", 404, "no endpoint GET /api/mark");
  expect_error("GET", "/api/log?limit=0", "", 400, "GET /api/log: limit=0: the number of rows, 1 to 10000");
  expect_error("GET", "/api/log?limit=abc", "", 400, "GET /api/log: limit=abc");
  expect_error("GET", "/api/log?limit=10001", "", 400, "GET /api/log: limit=10001");
  expect_error("PUT", "/api/vars/lot", std::string(70 * 1024, 'A'), 413, "the request body is over 65536 bytes");
  expect_error("PUT", "/api/vars/size", "3", 400, "");  // a variable no template uses
  expect_error("PUT", "/api/vars/lot", "A\x01", 400, "PUT /api/vars/lot: control characters");
  expect_error("POST", "/api/mark", "{\"lot\": 1}", 400, "POST /api/mark takes no body");
  expect_error("POST", "/api/mark?async=yes", "", 400, "POST /api/mark: async takes 1");
  expect_error("GET", "/api/serial/nope", "", 404, "SERIAL nope: the job uses no counter of that name");
  // Bytes that are not UTF-8, echoed in the error (found by fuzz_station_http): still a JSON answer.
  expect_error("GET", "/api/\xaa\xaa/log", "", 404, "no endpoint GET /api/\xef\xbf\xbd\xef\xbf\xbd/log");
  expect_error("PUT", "/api/vars/l\xff", "A", 400, "");
  EXPECT_EQ(call(*c, "POST", "/api/pause").body["state"], "paused");
  const Reply paused = call(*c, "POST", "/api/mark");
  EXPECT_EQ(paused.status, 409);
  EXPECT_EQ(paused.body["code"], "paused");
  EXPECT_EQ(call(*c, "POST", "/api/resume").body["state"], "idle");
  // Unchanged: nothing marked, nothing consumed, the old value kept.
  const Reply st = call(*c, "GET", "/api/status");
  EXPECT_EQ(st.body["state"], "idle");
  EXPECT_EQ(st.body["parts"], 0);
  EXPECT_EQ(call(*c, "GET", "/api/preview").body["text"], "SN 000041 LOT A00");
  EXPECT_EQ(s.close().size(), 0u);
}

// The operator page is served whole from the binary, calls only endpoints that exist, and its
// script is JavaScript that Node.js (an engine we did not write) parses. It is not run in a
// browser here (a headless-browser test is future work).
TEST(StationHttp, OperatorPageIsServedAndItsScriptParses) {
  Served s;
  httplib::Client c("127.0.0.1", s.http_port());
  const auto page = c.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_EQ(page->get_header_value("Content-Type"), "text/html; charset=utf-8");
  const std::string& html = page->body;
  for (const char* id : {"id=\"state\"", "id=\"mark\"", "id=\"abort\"", "id=\"pause\"", "id=\"reset\"", "id=\"next\"",
                         "id=\"last_text\"", "id=\"last_serials\"", "id=\"log\"", "call(\"GET\", \"/api/events\")",
                         "call(\"GET\", \"/api/preview.png\")", "id=\"token\"", "\"Authorization\": \"Bearer \" + t"})
    EXPECT_NE(html.find(id), std::string::npos) << id;
  EXPECT_EQ(html.find("http://"), std::string::npos);  // nothing fetched from elsewhere
  EXPECT_EQ(html.find("https://"), std::string::npos);
  // Every endpoint the script calls answers (not 404).
  for (const char* path : {"/api/status", "/api/preview", "/api/log?limit=50"}) {
    EXPECT_NE(html.find(std::string("\"") + path + "\""), std::string::npos) << path;
    EXPECT_EQ(c.Get(path)->status, 200) << path;
  }
  const std::size_t from = html.find("<script>"), to = html.find("</script>");
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  if (std::system("node --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "node (Debian nodejs) is not installed";
  const auto script = std::filesystem::temp_directory_path() / ("operator-page-" + std::to_string(::getpid()) + ".js");
  std::ofstream(script) << html.substr(from + 8, to - from - 8);
  const int rc = std::system(("node --check " + script.string()).c_str());
  std::filesystem::remove(script);
  EXPECT_EQ(rc, 0) << "node --check found a syntax error in the operator page's script";
}

TEST(StationHttp, ListensOnLoopbackOnlyAndRefusesAPortInUse) {
  EXPECT_EQ(parse_listen_address("192.168.1.5:8080", "--http", true).host, "192.168.1.5");  // with --token
  try {
    parse_listen_address("192.168.1.5:8080", "--http");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(
              "--http 192.168.1.5:8080: only loopback addresses (127.0.0.0/8) for a station without a token: give --token "
              "FILE to listen beyond loopback", 0), 0u) << e.what();
  }
  Served s;
  try {
    HttpServer second(*s.station, parse_listen_address("127.0.0.1:" + std::to_string(s.http_port()), "--http"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--http 127.0.0.1:" + std::to_string(s.http_port()) +
                                         ": cannot listen there (the port in use?)");
  }
}

}  // namespace
}  // namespace mark
