// Never repeat, never lose — under SIGKILL. A child process marks parts in a loop through the
// production path (PartRunner: allocate → mark on the simulated scanner → record the outcome)
// on one SQLite store; the parent kills it
// with SIGKILL at a random instant, again and again, then checks the store: no value issued
// twice, every issued value with exactly one audit row, every value a child was told it got
// still there, every part a child saw finish recorded done, no row left open, and the counter
// continuing right after the highest value issued.
//
// MARKER_KILLS sets the number of kills (default 400, about 20 s here);
// scripts/kill-test.sh runs the long version.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <random>
#include <sstream>
#include <thread>

#include "marker/job/sim_evaluator.hpp"
#include "marker/production/part_run.hpp"
#include "marker/store/digest.hpp"
#include "marker/store/utc_time.hpp"
#include "store_test_support.hpp"

namespace mark {
namespace {

enum Phase : int { starting = 0, allocating = 1, marking = 2, recording = 3, between = 4 };
constexpr const char* kPhaseNames[] = {"start-up and recovery", "allocation", "marking",
                                       "outcome recording", "between parts"};

struct Shared {
  std::atomic<int> phase;
  std::atomic<long long> parts;
};

// The job the child marks: the serial at 1 mm on the simulated SL10 head.
constexpr const char* kKillJob = R"({
  "format": "marker-job/1",
  "time_zone": "UTC",
  "counters": {"sn": {"start": 1}},
  "pens": {"p": {"speed_mm_s": 1000}},
  "objects": [{"name": "serial", "template": "{sn}", "height_mm": 1}]
})";

// The production path itself (PartRunner: allocate, mark on the simulator in virtual time,
// record), its phases told to the parent through shared memory and the values on a pipe.
[[noreturn]] void child_loop(const std::string& path, Shared* shared, int out_fd) {
  shared->phase = starting;
  const JobFile job = parse_job(kKillJob, "kill.json");
  const JobFonts fonts(job);
  MarkContext ctx;
  ctx.station = "kill-test";
  ctx.job = "kill.json";
  ctx.job_sha256 = sha256_hex(kKillJob);
  auto store = open_store(path, StoreAccess::create);
  test::create_counters(*store, job.used_counters(), "kill-test");
  SimScanner scanner(simulator_options(object_spec(job, job.objects.front(), "", fonts)));
  ctx.now = SystemClock().now();
  store->start_station(ctx);
  PartRunner runner(job, fonts, {}, scanner, *store, ctx);
  auto say = [&](char what, std::int64_t v) {
    char line[48];
    const int n = std::snprintf(line, sizeof line, "%c %lld\n", what, static_cast<long long>(v));
    if (write(out_fd, line, static_cast<std::size_t>(n)) != n) _exit(3);
  };
  SimEvaluator evaluator(scanner);  // as the command line marks: quality figures included
  PartOptions options;
  options.job.virtual_time = true;
  options.job.evaluator = &evaluator;
  options.phase = [&](PartPhase p, const std::map<std::string, std::int64_t>& serials) {
    switch (p) {
      case PartPhase::allocating: shared->phase = allocating; break;
      case PartPhase::marking:
        say('A', serials.at("sn"));
        shared->phase = marking;
        break;
      case PartPhase::recording: shared->phase = recording; break;
      case PartPhase::finished:
        shared->phase = between;
        say('D', serials.at("sn"));
        ++shared->parts;
        break;
    }
  };
  for (;;) {
    const PartResult part = runner.mark_next(SystemClock().now(), options);
    if (part.outcome != JobOutcome::done) _exit(4);
  }
}

int kills_wanted() {
  const char* env = std::getenv("MARKER_KILLS");
  return env ? std::max(1, std::atoi(env)) : 400;
}

TEST(SerialStoreKill, SigkillAtRandomInstantsNeverRepeatsOrLosesANumber) {
  const auto dir = test::fresh_store_dir("kill");
  const std::string path = (dir / "kill.serials.sqlite").string();
  auto* shared = static_cast<Shared*>(
      mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  ASSERT_NE(shared, MAP_FAILED);
  new (shared) Shared{};

  const int kills = kills_wanted();
  std::mt19937 rng(20260305);
  std::set<std::int64_t> told_allocated, told_done;
  int by_phase[5] = {};
  const auto t0 = std::chrono::steady_clock::now();
  // Calibration: one child runs undisturbed for a while, to learn how long start-up and a part
  // take. Then a fifth of the kills land uniformly in start-up (recovery), the rest uniformly
  // over two parts' time after it, so every phase is hit in proportion to its duration.
  double startup_us = 0, part_us = 0;
  {
    const auto c0 = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) child_loop(path, shared, open("/dev/null", O_WRONLY));
    while (shared->phase.load() == starting) std::this_thread::sleep_for(std::chrono::microseconds(50));
    const auto c1 = std::chrono::steady_clock::now();
    const long long p0 = shared->parts.load();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const long long p1 = shared->parts.load();
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
    startup_us = std::chrono::duration<double, std::micro>(c1 - c0).count();
    part_us = 500e3 / std::max(1LL, p1 - p0);
  }
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < kills; ++k) {
    int fds[2];
    ASSERT_EQ(pipe(fds), 0);
    shared->phase = starting;
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      close(fds[0]);
      try {
        child_loop(path, shared, fds[1]);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "kill-test child: %s\n", e.what());
        _exit(2);
      }
    }
    close(fds[1]);
    const double aim = unit(rng);
    if (aim < 0.2) {
      std::this_thread::sleep_for(std::chrono::microseconds(static_cast<long>(unit(rng) * startup_us)));
    } else if (aim < 0.3) {
      // The outcome write is a short step (a part's time is mostly marking and its evaluation),
      // which a uniformly drawn instant hardly ever hits: one kill in ten waits for it, spinning,
      // and strikes as soon as it begins (bounded, should a part never get there).
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(2);
      while (shared->phase.load() != recording && std::chrono::steady_clock::now() < give_up) {
      }
    } else {
      while (shared->phase.load() == starting) std::this_thread::sleep_for(std::chrono::microseconds(20));
      std::this_thread::sleep_for(std::chrono::microseconds(static_cast<long>(unit(rng) * 2 * part_us)));
    }
    const int phase = shared->phase.load();
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
        << "the child stopped by itself (status " << status << ") before kill " << k;
    ++by_phase[phase];
    std::string said;
    char buf[4096];
    for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) said.append(buf, static_cast<std::size_t>(n));
    close(fds[0]);
    std::istringstream lines(said);
    char what;
    long long v;
    while (lines >> what >> v) (what == 'A' ? told_allocated : told_done).insert(v);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  auto store = open_store(path, StoreAccess::existing);
  MarkContext ctx;
  ctx.station = "kill-test";
  ctx.now = SystemClock().now();
  const auto closed = store->start_station(ctx).closed;  // the last child's open row, if any
  const std::vector<std::int64_t> values = test::check_store_consistent(*store, "sn");
  ASSERT_FALSE(values.empty());
  // Consecutive from 1: a transaction a kill interrupted consumed nothing.
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(values[i], static_cast<std::int64_t>(i) + 1);
  for (std::int64_t v : told_allocated) EXPECT_TRUE(std::binary_search(values.begin(), values.end(), v)) << v;
  std::map<std::int64_t, Outcome> outcome_of;
  std::size_t open_rows = 0;
  for (const AuditRow& r : store->log()) {
    if (r.mark.kind == AuditKind::create) continue;
    if (!r.outcome) ++open_rows;
    else outcome_of[r.mark.serials.at("sn")] = r.outcome->outcome;
  }
  EXPECT_EQ(open_rows, 0u);
  for (std::int64_t v : told_done) EXPECT_EQ(outcome_of[v], Outcome::done) << v;
  std::size_t done = 0, void_ = 0;
  for (const auto& [v, o] : outcome_of) (o == Outcome::done ? done : void_) += 1;
  const Allocation next = store->allocate({{"sn", test::plain_counter()}}, ShiftTable{}, ctx,
                                          test::render_sn());
  EXPECT_EQ(next.serials.at("sn"), values.back() + 1);

  std::printf("[kill test] %d SIGKILLs in %.1f s; %zu numbers issued (%zu done, %zu void), "
              "%zu closed at the end, 0 repeated, 0 lost\n",
              kills, seconds, values.size(), done, void_, closed.size());
  std::printf("[kill test] undisturbed: start-up %.1f ms, one part %.1f ms\n", startup_us / 1e3,
              part_us / 1e3);
  std::printf("[kill test] kills by phase:");
  for (int p = 0; p < 5; ++p) std::printf(" %s %d%s", kPhaseNames[p], by_phase[p], p < 4 ? "," : "\n");
  EXPECT_GT(by_phase[allocating], 0);
  EXPECT_GT(by_phase[marking], 0);
  EXPECT_GT(by_phase[recording], 0);
  munmap(shared, sizeof(Shared));
  store.reset();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mark
