// The PostgreSQL serial store on a private server: 8 station processes allocate 1000 numbers
// each at the same time on one counter, aborting some parts; afterwards every number from 1 to
// 8000 was issued exactly once (no duplicates, no gaps — the aborted ones are recorded void),
// with one audit row each. Skips, with a message, where the server binaries are missing
// (scripts/setup.sh installs them, so CI runs it).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <random>

#include "marker/store/digest.hpp"
#include "marker/store/postgres_backend.hpp"
#include "marker/store/utc_time.hpp"
#include "postgres_server.hpp"
#include "store_test_support.hpp"

namespace mark {
namespace {

constexpr int kStations = 8;
constexpr int kPerStation = 1000;

// One station: its own connection, 1000 parts, every 16th aborted (on average).
[[noreturn]] void station(const std::string& url, int index) {
  try {
    SerialStore store(open_postgres_store(url));
    MarkContext ctx;
    ctx.station = "station-" + std::to_string(index);
    ctx.job = "line.json";
    ctx.job_sha256 = sha256_hex("line");
    ctx.now = SystemClock().now();
    store.start_station(ctx);
    const std::map<std::string, CounterSpec> counters{{"sn", test::plain_counter()}};
    std::mt19937 rng(static_cast<unsigned>(index));
    for (int i = 0; i < kPerStation; ++i) {
      ctx.now = SystemClock().now();
      const Allocation a = store.allocate(counters, ShiftTable{}, ctx, test::render_sn());
      OutcomeRecord o;
      o.time_utc = format_utc(SystemClock().now());
      if (rng() % 16 == 0) {
        o.outcome = Outcome::aborted;
        o.message = "operator stop";
      }
      store.record_outcome(a.mark_id, o);
    }
    _exit(0);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "station %d: %s\n", index, e.what());
    _exit(1);
  }
}

TEST(PostgresStore, EightStationsShareOneCounterWithoutDuplicatesOrGaps) {
  const auto bin = test::PostgresServer::find_binaries();
  if (bin.empty())
    GTEST_SKIP() << "PostgreSQL server binaries (initdb, pg_ctl) not found under "
                    "/usr/lib/postgresql/*/bin; scripts/setup.sh installs them";
  test::PostgresServer server(bin);
  {
    // The schema once up front, so the stations' first transactions measure allocation.
    SerialStore store(open_postgres_store(server.url()));
    EXPECT_EQ(store.describe().substr(0, 20), "postgresql://marker@");
    test::create_counters(store, {{"sn", test::plain_counter()}});
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<pid_t> pids;
  for (int i = 0; i < kStations; ++i) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) station(server.url(), i);
    pids.push_back(pid);
  }
  for (pid_t pid : pids) {
    int status = 0;
    waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a station failed";
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  SerialStore store(open_postgres_store(server.url()));
  const std::vector<std::int64_t> values = test::check_store_consistent(store, "sn");
  ASSERT_EQ(values.size(), static_cast<std::size_t>(kStations * kPerStation));
  for (std::size_t i = 0; i < values.size(); ++i)
    ASSERT_EQ(values[i], static_cast<std::int64_t>(i) + 1) << "a gap or a duplicate";
  std::map<std::string, int> per_station;
  int aborted = 0;
  for (const AuditRow& r : store.log()) {
    if (r.mark.kind == AuditKind::create) continue;
    ASSERT_TRUE(r.outcome) << "row " << r.id << " left open";
    ++per_station[r.mark.station];
    if (r.outcome->outcome == Outcome::aborted) ++aborted;
  }
  EXPECT_EQ(per_station.size(), static_cast<std::size_t>(kStations));
  for (const auto& [name, n] : per_station) EXPECT_EQ(n, kPerStation) << name;
  EXPECT_GT(aborted, 0);
  std::printf("[postgres] %d stations × %d parts in %.1f s (%.0f allocations/s), %d void, "
              "0 duplicates, 0 gaps\n",
              kStations, kPerStation, seconds, kStations * kPerStation / seconds, aborted);

  // The counter continues after the highest issued value.
  MarkContext ctx;
  ctx.station = "check";
  ctx.now = SystemClock().now();
  EXPECT_EQ(store.allocate({{"sn", test::plain_counter()}}, ShiftTable{}, ctx, test::render_sn())
                .serials.at("sn"),
            kStations * kPerStation + 1);
  // Station names are exclusive while a process holds them.
  SerialStore second(open_postgres_store(server.url()));
  store.start_station(ctx);
  EXPECT_THROW(second.start_station(ctx), StoreError);
}

}  // namespace
}  // namespace mark
