// `marker serve` killed with SIGKILL in the middle of a part (issue 22: "Kill the server with
// SIGKILL mid-mark, restart it: the interrupted serial is void, the next one continues"). The
// real binary as a child process, in real time so the part lasts seconds, the line protocol on a
// free loopback port; the store is read back from its file afterwards.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "tests/marker/station/served_station.hpp"

namespace mark {
namespace {

// One SN per part at 100 mm/s: a few seconds of real time on the simulated scanner.
constexpr const char* kSlowJob = R"({
  "format": "marker-job/1", "head": "SL10", "time_zone": "UTC",
  "counters": {"serial": {"start": 41, "width": 6}},
  "pens": {"slow": {"speed_mm_s": 100, "power_pct": 100, "frequency_khz": 40}},
  "objects": [{"name": "serial", "pen": "slow", "template": "SN {serial}", "height_mm": 3, "x_mm": -20, "y_mm": 0}]
})";

std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// `marker serve` on the job and store, its stderr in `log`; the port it logged it listens on.
struct ServeProcess {
  pid_t pid = -1;
  int port = 0;

  ServeProcess(const std::filesystem::path& job, const std::filesystem::path& store, const std::filesystem::path& log) {
    const std::string binary = std::string(MARKER_BINARY_DIR) + "/marker/marker";
    pid = fork();
    if (pid == 0) {
      if (!freopen("/dev/null", "w", stdout) || !freopen(log.c_str(), "w", stderr)) _exit(99);
      execl(binary.c_str(), binary.c_str(), "serve", "--job", job.c_str(), "--store", store.c_str(), "--station", "s1",
            "--create-counters", "--listen", "127.0.0.1:0", static_cast<char*>(nullptr));
      _exit(98);
    }
    const auto t0 = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60)) {
      const std::string said = read_all(log);
      const std::size_t at = said.find("listening on 127.0.0.1:");
      if (at != std::string::npos && said.find(' ', at + 23) != std::string::npos) {
        port = std::stoi(said.substr(at + 23));
        return;
      }
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) == pid) {
        pid = -1;
        ADD_FAILURE() << "marker serve ended before it listened: " << said;
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ADD_FAILURE() << "marker serve did not listen within 60 s: " << read_all(log);
  }
  // The signal, then the exit status as waitpid gives it.
  int stop(int signal) {
    if (pid <= 0) return -1;
    kill(pid, signal);
    int status = 0;
    waitpid(pid, &status, 0);
    pid = -1;
    return status;
  }
  ~ServeProcess() {
    if (pid > 0) stop(SIGKILL);
  }
};

TEST(ServeKill, SigkillMidMarkVoidsThatSerialAndTheRestartContinues) {
  const auto dir = test::fresh_store_dir("serve-kill");
  const auto job = dir / "slow.json", store = dir / "line.serials.sqlite";
  std::ofstream(job) << kSlowJob;
  {
    ServeProcess serve(job, store, dir / "first.log");
    ASSERT_GT(serve.port, 0);
    test::LineClient c(serve.port);
    ASSERT_EQ(c.ask("MARK ASYNC"), "OK started");
    // Killed while the part is on the scanner: its serial is durable, its outcome never written.
    const auto t0 = std::chrono::steady_clock::now();
    std::string status;
    while ((status = c.ask("STATUS")).rfind("OK state=marking", 0) != 0 &&
           std::chrono::steady_clock::now() - t0 < std::chrono::seconds(30))
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_EQ(status.rfind("OK state=marking", 0), 0u) << status;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    status = c.ask("STATUS");
    ASSERT_EQ(status.rfind("OK state=marking", 0), 0u) << "the part ended before the kill (make it longer): " << status;
    const int killed = serve.stop(SIGKILL);
    ASSERT_TRUE(WIFSIGNALED(killed));
  }
  {
    auto rows = open_store(store.string(), StoreAccess::read_only)->log();
    std::erase_if(rows, [](const AuditRow& r) { return r.mark.kind == AuditKind::create; });
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].mark.serials.at("serial"), 41);
    EXPECT_FALSE(rows[0].outcome) << "the killed part has no outcome until a station starts again";
  }
  {
    ServeProcess serve(job, store, dir / "second.log");
    ASSERT_GT(serve.port, 0);
    test::LineClient c(serve.port);
    EXPECT_EQ(c.ask("SERIAL serial"), "OK serial=42") << "the next number after the void one";
    const std::string r = c.ask("MARK");
    EXPECT_EQ(r.rfind("OK id=", 0), 0u) << r;
    EXPECT_NE(r.find(" serial=42"), std::string::npos) << r;
    const int stopped = serve.stop(SIGTERM);
    EXPECT_TRUE(WIFEXITED(stopped) && WEXITSTATUS(stopped) == 0) << read_all(dir / "second.log");
  }
  auto rows = open_store(store.string(), StoreAccess::read_only)->log();
  std::erase_if(rows, [](const AuditRow& r) { return r.mark.kind == AuditKind::create; });
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].mark.serials.at("serial"), 41);
  ASSERT_TRUE(rows[0].outcome);
  EXPECT_EQ(rows[0].outcome->outcome, Outcome::aborted) << "the interrupted serial is void";
  EXPECT_EQ(rows[1].mark.serials.at("serial"), 42);
  ASSERT_TRUE(rows[1].outcome);
  EXPECT_EQ(rows[1].outcome->outcome, Outcome::done);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mark
