// `marker serve --token FILE` (docs/station.md, "Token"): the token file's checks, the
// comparison's results, and both interfaces end to end on real loopback sockets — the TCP line
// protocol (AUTH first) and HTTP (Authorization: Bearer) — with what changed read back from the
// store after the station closed it, not from the station's own replies. The last test runs the
// built `marker serve` binary on 0.0.0.0 and talks to it over 127.0.0.1.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "base/error.hpp"
#include "marker/station/line_auth.hpp"
#include "marker/station/station_token.hpp"
#include "tests/marker/cli_runner.hpp"
#include "tests/marker/station/served_station.hpp"
// Last: it brings <resolv.h>, whose `_res` macro breaks Eigen's headers included after it.
#include <httplib.h>

namespace mark {
namespace {

using test::Served;
using Client = test::LineClient;

constexpr const char* kToken = "Tq3x9Vb2LmZ8wK4pR7sN";  // 20 characters

// `text` in a fresh file of `dir` with permission bits `mode`; its path.
std::string token_file(const std::filesystem::path& dir, const std::string& name, const std::string& text,
                       mode_t mode = 0600) {
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  ::chmod(path.c_str(), mode);
  return path.string();
}

std::string refusal(const std::string& path) {
  try {
    read_station_token(path, "--token");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(StationToken, ComparisonResults) {
  const std::string t = kToken;
  EXPECT_TRUE(token_matches(t, t));
  EXPECT_TRUE(token_matches(t, std::string(kToken)));  // another buffer, same bytes
  std::string last = t;
  last.back() = 'x';
  EXPECT_FALSE(token_matches(t, last));                 // same length, last byte differs
  std::string first = t;
  first.front() = 'x';
  EXPECT_FALSE(token_matches(t, first));                // same length, first byte differs
  EXPECT_FALSE(token_matches(t, t.substr(0, t.size() - 1)));  // a prefix
  EXPECT_FALSE(token_matches(t, t + "A"));              // longer
  EXPECT_FALSE(token_matches(t, t + std::string(1, '\0')));  // longer by a zero byte (past-end bytes read as 0)
  EXPECT_FALSE(token_matches(t, ""));
  EXPECT_FALSE(token_matches("", ""));                  // no token is never a match
  EXPECT_FALSE(token_matches(t, t + std::string(kTokenCompareMax, 'A')));  // longer than the window
  const std::string longest(kTokenCompareMax, 'k');
  EXPECT_TRUE(token_matches(longest, longest));
  EXPECT_FALSE(token_matches(longest, longest + "k"));
}

TEST(StationToken, FileIsCheckedLikeAnSshKey) {
  const auto dir = test::fresh_temp_dir("marker_token_files");
  EXPECT_EQ(read_station_token(token_file(dir, "ok", std::string(kToken) + "\n"), "--token"), kToken);
  EXPECT_EQ(read_station_token(token_file(dir, "crlf", std::string(kToken) + "\r\nsecond line\n"), "--token"), kToken);
  EXPECT_EQ(read_station_token(token_file(dir, "bare", kToken, 0400), "--token"), kToken);

  const std::string open = token_file(dir, "open", kToken, 0644);
  EXPECT_EQ(refusal(open), "--token " + open + ": the token file can be read or written by group or others; chmod 600 " + open);
  EXPECT_NE(refusal(token_file(dir, "group", kToken, 0620)).find("chmod 600"), std::string::npos);
  const std::string missing = (dir / "missing").string();
  EXPECT_EQ(refusal(missing), "--token " + missing + ": cannot read the token file: No such file or directory");
  const std::string short15 = token_file(dir, "short", "123456789012345\n");
  EXPECT_EQ(refusal(short15), "--token " + short15 + ": the token has 15 characters; it needs at least 16");
  EXPECT_EQ(read_station_token(token_file(dir, "sixteen", "1234567890123456\n"), "--token"), "1234567890123456");
  EXPECT_NE(refusal(token_file(dir, "empty", "")).find("the token file is empty"), std::string::npos);
  EXPECT_NE(refusal(token_file(dir, "blank", "\n" + std::string(kToken))).find("the token's line is empty"),
            std::string::npos);
  EXPECT_NE(refusal(token_file(dir, "space", "abcdefgh ijklmnopq")).find("a space or a control character"),
            std::string::npos);
  EXPECT_NE(refusal(token_file(dir, "tab", "abcdefgh\tijklmnopq")).find("a space or a control character"),
            std::string::npos);
  EXPECT_NE(refusal(dir.string()).find("not a regular file"), std::string::npos);
  if (::geteuid() != 0) {  // root reads any file: the unreadable case needs another user
    const std::string locked = token_file(dir, "locked", kToken, 0200);
    EXPECT_NE(refusal(locked).find("cannot read the token file"), std::string::npos) << refusal(locked);
  }
  std::filesystem::remove_all(dir);
}

TEST(StationTcpToken, NothingRunsBeforeAuth) {
  Served s(true, 8, {}, kToken);
  Client c(s.port());
  const std::string refused = "ERR auth give AUTH <token> first; nothing else runs before it";
  EXPECT_EQ(c.ask("MARK"), refused);
  EXPECT_EQ(c.ask("MARK ASYNC"), refused);
  EXPECT_EQ(c.ask("SET lot B99"), refused);
  EXPECT_EQ(c.ask("STATUS"), refused);
  EXPECT_EQ(c.ask("SERIAL serial"), refused);
  EXPECT_EQ(c.ask("ABORT"), refused);
  EXPECT_EQ(c.ask("LOAD /etc/passwd"), refused);
  // A second session that authenticates sees nothing changed: the serial and the variable.
  Client authed(s.port());
  EXPECT_EQ(authed.ask(std::string("AUTH ") + kToken), "OK auth");
  EXPECT_EQ(authed.ask("SERIAL serial"), "OK serial=41");
  EXPECT_EQ(authed.ask("PREVIEW"), "OK serial=41 text=\"SN 000041 LOT A00\"");
  EXPECT_EQ(s.close().size(), 0u);  // the store: no part, no serial issued
}

TEST(StationTcpToken, ThreeWrongTokensCloseTheSession) {
  Served s(true, 8, {}, kToken);
  Client c(s.port());
  EXPECT_EQ(c.ask("AUTH Tq3x9Vb2LmZ8wK4pR7sX"), "ERR auth wrong token");  // last character wrong
  EXPECT_EQ(c.ask("AUTH"), "ERR auth wrong token");
  EXPECT_EQ(c.ask("MARK"), "ERR auth give AUTH <token> first; nothing else runs before it");
  EXPECT_EQ(c.ask(std::string("auth ") + kToken + "x"), "ERR auth wrong token; closing after 3 wrong tries");
  EXPECT_EQ(c.line(), "");  // closed by the station
  // Another session still may authenticate and mark.
  Client d(s.port());
  EXPECT_EQ(d.ask(std::string("AUTH ") + kToken), "OK auth");
  EXPECT_EQ(d.ask("MARK").substr(0, 30), "OK id=2 outcome=done serial=41");
  test::expect_one_part(s.close(), 2, 41, Outcome::done);
}

TEST(StationTcpToken, RightTokenThenMarkWorks) {
  Served s(true, 8, {}, kToken);
  Client c(s.port());
  EXPECT_EQ(c.ask(std::string("AUTH ") + kToken + "\r"), "OK auth");  // a CRLF client (nc -C)
  EXPECT_EQ(c.ask("SET lot A17"), "OK lot=A17");
  EXPECT_EQ(c.ask("MARK").substr(0, 55), "OK id=2 outcome=done serial=41 text=\"SN 000041 LOT A17\"");
  // A wrong AUTH later takes the session's authentication back.
  EXPECT_EQ(c.ask("AUTH nope"), "ERR auth wrong token");
  EXPECT_EQ(c.ask("MARK").substr(0, 9), "ERR auth ");
  test::expect_one_part(s.close(), 2, 41, Outcome::done, "SN 000041 LOT A17");
}

TEST(StationTcpToken, AuthWithoutATokenSetIsAcceptedAndChangesNothing) {
  Served s;
  Client c(s.port());
  EXPECT_EQ(c.ask("AUTH anything"), "OK auth (no token set)");
  EXPECT_EQ(c.ask("SERIAL serial"), "OK serial=41");
  EXPECT_EQ(s.close().size(), 0u);
}

TEST(StationTcpToken, LineAuthRunsNoVerbBeforeTheRightToken) {
  LineAuth auth(kToken);
  EXPECT_FALSE(auth.authenticated());
  const auto v = auth.check("MARK");
  EXPECT_TRUE(v.handled);
  EXPECT_FALSE(v.close);
  EXPECT_EQ(v.log, "refused a command before AUTH");
  EXPECT_EQ(auth.check("AUTH short").log, "wrong token (1 of 3)");
  EXPECT_EQ(auth.check(std::string("AUTH ") + kToken).reply, "OK auth");
  EXPECT_TRUE(auth.authenticated());
  EXPECT_FALSE(auth.check("MARK").handled);  // passes to the station
  EXPECT_EQ(auth.check("AUTH x").log.find(kToken), std::string::npos);  // the log never holds a token
}

// --- HTTP ---

httplib::Result post_mark(httplib::Client& c, const std::string& bearer) {
  httplib::Headers h;
  if (!bearer.empty()) h.emplace("Authorization", bearer);
  return c.Post("/api/mark", h, "", "application/json");
}

TEST(StationHttpToken, EveryApiRequestNeedsTheBearerToken) {
  Served s(true, 8, {}, kToken);
  httplib::Client c("127.0.0.1", s.http_port());
  c.set_read_timeout(std::chrono::seconds(30));
  for (const std::string& bearer : {std::string(), std::string("Bearer wrong-token-0123456789"),
                                   std::string("Basic ") + kToken, std::string("Bearer ") + kToken + "x"}) {
    const auto r = post_mark(c, bearer);
    ASSERT_TRUE(r) << bearer;
    EXPECT_EQ(r->status, 401) << bearer;
    EXPECT_EQ(r->get_header_value("WWW-Authenticate"), "Bearer");
    const auto body = nlohmann::json::parse(r->body, nullptr, false);
    ASSERT_TRUE(body.is_object()) << r->body;
    EXPECT_TRUE(body["error"].is_string());
    EXPECT_EQ(r->body.find(kToken), std::string::npos);
  }
  for (const char* path : {"/api/status", "/api/serial/serial", "/api/log", "/api/events", "/api/preview.png", "/api/nothing"}) {
    const auto r = c.Get(path);
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 401) << path;
  }
  httplib::Headers h{{"Authorization", "Bearer wrong"}};
  const auto put = c.Put("/api/vars/lot", h, "B99", "text/plain");
  ASSERT_TRUE(put);
  EXPECT_EQ(put->status, 401);
  // The page carries no data: anyone may load it (its script then asks for the token).
  const auto page = c.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);

  const auto ok = post_mark(c, std::string("Bearer ") + kToken);
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->status, 200) << ok->body;
  EXPECT_EQ(nlohmann::json::parse(ok->body)["serials"]["serial"], 41);
  c.set_bearer_token_auth(kToken);  // httplib's own way of sending it: the same header
  const auto st = c.Get("/api/serial/serial");
  ASSERT_TRUE(st);
  EXPECT_EQ(st->status, 200);
  EXPECT_EQ(nlohmann::json::parse(st->body)["next"], 42);
  // One part in the store, from the one authenticated request; the refused PUT changed nothing.
  test::expect_one_part(s.close(), 2, 41, Outcome::done, "SN 000041 LOT A00");
}

// --- marker serve ---

TEST(ServeToken, BeyondLoopbackNeedsAToken) {
  const auto dir = test::fresh_temp_dir("marker_serve_token");
  const std::string job = (dir / "line.json").string();
  std::ofstream(job) << test::kStationJob;
  auto r = test::run_cli({"serve", "--job", job, "--listen", "0.0.0.0:0"});
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("--listen 0.0.0.0:0: only loopback addresses (127.0.0.0/8) for a station without a token: "
                       "give --token FILE to listen beyond loopback"),
            std::string::npos)
      << r.err;
  r = test::run_cli({"serve", "--job", job, "--http", "10.0.0.1:0"});
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("--http 10.0.0.1:0: only loopback"), std::string::npos) << r.err;
  const std::string open = token_file(dir, "open.token", std::string(kToken) + "\n", 0644);
  r = test::run_cli({"serve", "--job", job, "--listen", "0.0.0.0:0", "--token", open});
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("--token " + open + ": the token file can be read or written by group or others; chmod 600"),
            std::string::npos)
      << r.err;
  const std::string short15 = token_file(dir, "short.token", "123456789012345\n");
  r = test::run_cli({"serve", "--job", job, "--listen", "0.0.0.0:0", "--token", short15});
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("the token has 15 characters; it needs at least 16"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

// The built binary on 0.0.0.0 with a token, a client on 127.0.0.1: AUTH first, then it answers;
// SIGTERM ends it with exit 0.
TEST(ServeToken, ServesOnAnyAddressWithAToken) {
  const auto dir = test::fresh_temp_dir("marker_serve_token_any");
  const std::string job = (dir / "line.json").string();
  std::ofstream(job) << test::kStationJob;
  const std::string token = token_file(dir, "station.token", std::string(kToken) + "\n");
  const std::string log = (dir / "serve.log").string();
  const std::string binary = std::string(MARKER_BINARY_DIR) + "/marker/marker";
  const std::string store = (dir / "serials.sqlite").string();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (!freopen(log.c_str(), "w", stderr)) _exit(99);
    execl(binary.c_str(), binary.c_str(), "serve", "--job", job.c_str(), "--listen", "0.0.0.0:0", "--http", "0.0.0.0:0",
          "--token", token.c_str(), "--store", store.c_str(), "--station", "s1", "--create-counters", "--virtual-time",
          "--device", "sim", static_cast<char*>(nullptr));
    _exit(98);
  }
  int port = 0;
  std::string text;
  for (int i = 0; i < 400 && port == 0; ++i) {  // at most 20 s for the station to start
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::stringstream ss;
    ss << std::ifstream(log).rdbuf();
    text = ss.str();
    const std::size_t at = text.find("listening on 0.0.0.0:");
    if (at != std::string::npos) port = std::atoi(text.c_str() + at + 21);
  }
  ASSERT_GT(port, 0) << text;
  {
    Client c(port);
    EXPECT_EQ(c.ask("STATUS"), "ERR auth give AUTH <token> first; nothing else runs before it");
    EXPECT_EQ(c.ask(std::string("AUTH ") + kToken), "OK auth");
    EXPECT_EQ(c.ask("SERIAL serial"), "OK serial=41");
  }
  ::kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  std::stringstream ss;
  ss << std::ifstream(log).rdbuf();
  text = ss.str();
  EXPECT_NE(text.find("auth: 127.0.0.1:"), std::string::npos) << text;  // the refusal, with the peer
  EXPECT_EQ(text.find(kToken), std::string::npos) << text;              // never the token
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mark

namespace mark {
namespace {

// The operator page's own script, run by Node.js (its fetch is undici: an HTTP client we did
// not write) against a station with a token, with just enough of a DOM to hold what it shows:
// it asks for the token on the first 401, then with the token typed marks a part from its Mark
// button and shows the part the station recorded. Not a browser (a browser test is future work).
constexpr const char* kPageHarness = R"js(
const base = process.argv[2], token = process.argv[3];
const els = {};
const el = id => els[id] || (els[id] = {id, textContent: "", className: "", hidden: id === "login", value: "", src: "",
  tBodies: [{textContent: "", insertRow: () => ({insertCell: () => ({})})}]});
globalThis.document = {getElementById: el};
const stored = {};
globalThis.sessionStorage = {getItem: k => (k in stored ? stored[k] : null), setItem: (k, v) => { stored[k] = String(v); }};
const realFetch = globalThis.fetch;
let streaming = false;  // the page's /api/events answered: a part's end reaches it from now on
globalThis.fetch = async (path, options) => {
  const r = await realFetch(base + path, options);
  if (path === "/api/events" && r.ok) streaming = true;
  return r;
};
URL.createObjectURL = () => "blob:picture";
URL.revokeObjectURL = () => {};
// Generous: under a loaded ctest -j2 the station's first preview picture alone took seconds.
setTimeout(() => {
  const shown = Object.fromEntries(Object.entries(els).map(([k, v]) => [k, {text: v.textContent, hidden: v.hidden, src: v.src}]));
  console.log("timeout streaming=" + streaming + " " + JSON.stringify(shown));
  process.exit(1);
}, 60000);
const until = (what, check) => new Promise(done => {
  const poll = setInterval(() => { if (check()) { clearInterval(poll); console.log(what); done(); } }, 20);
});
(async () => {
  await until("login shown", () => !el("login").hidden);
  el("token").value = token;
  el("login").onsubmit({preventDefault() {}});
  await until("idle shown", () => streaming && el("state").textContent === "idle" && el("picture").src === "blob:picture");
  el("mark").onclick();
  await until("part shown", () => el("last_outcome").textContent === "done");
  console.log("part " + el("last_id").textContent + " " + el("last_serials").textContent + " " + el("last_text").textContent);
  process.exit(0);
})();
)js";

TEST(StationHttpToken, OperatorPageScriptAsksForTheTokenThenMarks) {
  if (std::system("node --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "node (Debian nodejs) is not installed";
  Served s(true, 8, {}, kToken);
  httplib::Client c("127.0.0.1", s.http_port());
  const auto page = c.Get("/");
  ASSERT_TRUE(page);
  const std::string& html = page->body;
  const std::size_t from = html.find("<script>"), to = html.find("</script>");
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  const auto dir = test::fresh_temp_dir("marker_page_token");
  const auto script = dir / "page.js";
  std::ofstream(script) << kPageHarness << html.substr(from + 8, to - from - 8);
  const std::string command = "timeout 90 node " + script.string() + " http://127.0.0.1:" +
                              std::to_string(s.http_port()) + " " + kToken + " 2>&1";
  FILE* p = ::popen(command.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string out;
  char chunk[1024];
  for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, p)) > 0;) out.append(chunk, n);
  const int status = ::pclose(p);
  EXPECT_EQ(status, 0) << out;
  EXPECT_EQ(out, "login shown\nidle shown\npart shown\npart 2 serial = 41 SN 000041 LOT A00\n");
  std::filesystem::remove_all(dir);
  test::expect_one_part(s.close(), 2, 41, Outcome::done, "SN 000041 LOT A00");
}

}  // namespace
}  // namespace mark
