// The store that runs for months: a generated SQLite store of N audit rows (default 10 million,
// each a part marked done with its issue, outcome and marked text, as the store writes them),
// then what a station and its readers see on it:
//
//   - `log --limit 100` and `log --since` (the last 1000 rows' time): rows read, wall time, and the
//     growth of the process's peak resident memory over the read (VmHWM after resetting it through
//     /proc/self/clear_refs) — constant memory means a few MiB, whatever N;
//   - a full streaming read of the log: the same growth, over every row;
//   - allocation + outcome latency per part (median, p99, max) with no reader, and while another
//     connection streams the whole log (read-only transaction on a WAL snapshot).
//
//   store_log [--rows N] [--dir DIR] [--parts P] [--keep]
// Kept out of CTest (a 10 M-row store takes minutes and gigabytes); docs/store.md has its figures.
#include <sqlite3.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "marker/store/open_store.hpp"
#include "marker/store/utc_time.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using mark::AuditFilter;
using mark::AuditRow;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Peak resident memory (VmHWM, kB), and resetting it.
long peak_kb() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}
void reset_peak() { std::ofstream("/proc/self/clear_refs") << "5"; }

void exec(sqlite3* db, const std::string& sql) {
  char* err = nullptr;
  if (sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
    std::fprintf(stderr, "store_log: %s: %s\n", sql.substr(0, 60).c_str(), err ? err : "?");
    std::exit(1);
  }
}

// N parts marked done, appended straight through SQL in chunks (the store's own allocation
// would take hours for 10 M rows): the same tables and indexes, one part a second from
// 2026-01-01, counter "sn" continuing after them.
void generate(const std::string& path, long long rows) {
  {
    auto store = mark::open_store(path, mark::StoreAccess::create);
    mark::MarkContext ctx;
    ctx.station = "generator";
    mark::CounterSpec sn;
    sn.name = "sn";
    sn.time_zone = mark::TimeZone::named("UTC");
    store->create_missing({{"sn", sn}}, mark::ShiftTable{}, ctx);
  }
  sqlite3* db = nullptr;
  sqlite3_open(path.c_str(), &db);
  exec(db, "PRAGMA synchronous=OFF");
  const long long chunk = 500'000;
  const std::string sha(64, 'a');
  for (long long from = 0; from < rows; from += chunk) {
    const long long n = std::min(chunk, rows - from);
    const std::string x = "(" + std::to_string(from) + " + x)";
    exec(db, "BEGIN");
    exec(db, "WITH RECURSIVE c(x) AS (SELECT 1 UNION ALL SELECT x + 1 FROM c WHERE x < " + std::to_string(n) +
                 ") INSERT INTO marks(time_utc, station, job, job_sha256, kind, remark_of, objects, serials) "
                 "SELECT strftime('%Y-%m-%dT%H:%M:%S', 1767225600 + " + x + ", 'unixepoch') || '.000000Z', "
                 "'line-' || (" + x + " % 4), 'bracket.json', '" + sha + "', 'mark', NULL, "
                 "json_array(json_object('name', 'serial', 'text', 'SN ' || " + x + ")), "
                 "json_object('sn', " + x + ") FROM c");
    const std::string last = "(SELECT max(id) FROM marks)";
    const std::string first = "(" + last + " - " + std::to_string(n) + ")";
    exec(db, "INSERT INTO issues SELECT 'sn', '', 0, json_extract(serials, '$.sn'), 0, id FROM marks WHERE id > " +
                 first);
    exec(db, "INSERT INTO outcomes SELECT id, time_utc, 'done', '', '{\"samples\": 23817, \"mark_time_s\": 0.1568}' "
             "FROM marks WHERE id > " + first);
    exec(db, "INSERT INTO marked_texts SELECT json_extract(objects, '$[0].text'), 'serial', id FROM marks WHERE id > " +
                 first);
    exec(db, "COMMIT");
    std::fprintf(stderr, "\rgenerated %lld rows", from + n);
  }
  exec(db, "UPDATE counters SET next_value = " + std::to_string(rows + 1) + " WHERE name = 'sn'");
  exec(db, "PRAGMA wal_checkpoint(TRUNCATE)");
  sqlite3_close(db);
  std::fprintf(stderr, "\n");
}

struct Read {
  long long rows = 0;
  double seconds = 0;
  long growth_kb = 0;
};

Read read(const std::string& path, const AuditFilter& f) {
  auto store = mark::open_store(path, mark::StoreAccess::read_only);
  reset_peak();
  const long before = peak_kb();
  const auto t = Clock::now();
  Read r;
  store->read_log(f, [&](const AuditRow&) {
    ++r.rows;
    return true;
  });
  r.seconds = seconds_since(t);
  r.growth_kb = peak_kb() - before;
  return r;
}

struct Latency {
  double median_ms = 0, p99_ms = 0, max_ms = 0;
};

Latency allocate_parts(mark::SerialStore& store, int parts) {
  const std::map<std::string, mark::CounterSpec> counters = [] {
    mark::CounterSpec sn;
    sn.name = "sn";
    sn.time_zone = mark::TimeZone::named("UTC");
    return std::map<std::string, mark::CounterSpec>{{"sn", sn}};
  }();
  mark::MarkContext ctx;
  ctx.station = "bench";
  std::vector<double> ms;
  for (int i = 0; i < parts; ++i) {
    ctx.now = mark::SystemClock().now();
    const auto t = Clock::now();
    const mark::Allocation a = store.allocate(counters, mark::ShiftTable{}, ctx, [](const auto& serials) {
      return std::vector<mark::ObjectText>{{"serial", "SN " + std::to_string(serials.at("sn")), true}};
    });
    mark::OutcomeRecord done;
    done.time_utc = a.time_utc;
    store.record_outcome(a.mark_id, done);
    ms.push_back(seconds_since(t) * 1e3);
  }
  std::sort(ms.begin(), ms.end());
  return {ms[ms.size() / 2], ms[std::min(ms.size() - 1, ms.size() * 99 / 100)], ms.back()};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"store_log: audit-log reads and allocation latency on a generated store of N rows"};
  long long rows = 10'000'000;
  int parts = 300;
  std::string dir = std::filesystem::temp_directory_path() / "marker-store-log";
  bool keep = false;
  app.add_option("--rows", rows, "audit rows to generate")->check(CLI::Range(1000LL, 100'000'000LL));
  app.add_option("--parts", parts, "parts allocated per latency figure")->check(CLI::Range(10, 100'000));
  app.add_option("--dir", dir, "folder of the generated store (reused when it holds N rows)");
  app.add_flag("--keep", keep, "keep the store for another run");
  CLI11_PARSE(app, argc, argv);

  std::filesystem::create_directories(dir);
  const std::string path = dir + "/store-" + std::to_string(rows) + ".sqlite";
  if (!std::filesystem::exists(path)) {
    const auto t = Clock::now();
    generate(path, rows);
    std::printf("generated %lld rows in %.0f s: %.2f GB\n", rows, seconds_since(t),
                static_cast<double>(std::filesystem::file_size(path)) / 1e9);
  }

  AuditFilter limit;
  limit.limit = 100;
  AuditFilter since;
  since.since_utc = mark::format_utc(mark::SysTime{std::chrono::seconds(1767225600 + rows - 1000)});
  const Read l = read(path, limit);
  const Read s = read(path, since);
  std::printf("log --limit 100:          %lld rows in %.3f s, peak memory +%ld kB\n", l.rows, l.seconds, l.growth_kb);
  std::printf("log --since (last 1000):  %lld rows in %.3f s, peak memory +%ld kB\n", s.rows, s.seconds, s.growth_kb);

  mark::StoreSettings settings;
  settings.retry = {3, 20, 200};
  auto store = mark::open_store(path, mark::StoreAccess::existing, settings);
  mark::MarkContext ctx;
  ctx.station = "bench";
  store->start_station(ctx);
  const Latency alone = allocate_parts(*store, parts);
  std::printf("allocation + outcome, no reader:        median %.2f ms, p99 %.2f ms, max %.2f ms (%d parts)\n",
              alone.median_ms, alone.p99_ms, alone.max_ms, parts);

  std::atomic<bool> stop{false};
  Read full;
  std::thread reader([&] {
    auto r = mark::open_store(path, mark::StoreAccess::read_only);
    reset_peak();
    const long before = peak_kb();
    const auto t = Clock::now();
    r->read_log(AuditFilter{}, [&](const AuditRow&) {
      ++full.rows;
      return !stop.load();
    });
    full.seconds = seconds_since(t);
    full.growth_kb = peak_kb() - before;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the read under way
  const Latency busy = allocate_parts(*store, parts);
  const bool finished = !stop.exchange(true);
  reader.join();
  std::printf("allocation + outcome, full log read on: median %.2f ms, p99 %.2f ms, max %.2f ms (%d parts)\n",
              busy.median_ms, busy.p99_ms, busy.max_ms, parts);
  std::printf("full log read (streamed, %s): %lld rows in %.1f s, peak memory +%ld kB\n",
              finished ? "stopped after the allocations" : "whole", full.rows, full.seconds, full.growth_kb);
  store.reset();
  if (!keep) std::filesystem::remove_all(dir);
  return 0;
}
