#pragma once
// The store fails at each step of a part (store_faults.hpp: the fault made to happen for real),
// once or for good; then the station starts again. Whatever happened, a part marked in full
// ends up logged done, a part refused before the laser consumed nothing, and no row is left
// open. Shared by the SQLite and the PostgreSQL suites; each prints its matrix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "marker/job/sim_evaluator.hpp"
#include "marker/production/part_run.hpp"
#include "marker/store/digest.hpp"
#include "marker/store/serial_store.hpp"
#include "marker/store/utc_time.hpp"

namespace mark::test {

struct FaultCase {
  StoreStep step;
  StoreFaultKind kind;
  int attempts;  // failing attempts; 0: every one
};

struct FaultRow {
  FaultCase c;
  std::string during;  // what the run said about the part
  std::string after;   // the part's row after the next start
};

using OpenStore = std::function<std::unique_ptr<SerialStore>(StoreSettings)>;

// Part 1 of a one-object job under the fault, then the station's next start (a new store
// object, as a new process has). `tag` keeps the texts of the cases apart in a shared store.
inline FaultRow run_fault_case(const OpenStore& open, const FaultCase& c, const std::string& journal_dir,
                               const std::string& tag) {
  const std::string text = R"({"format": "marker-job/1", "time_zone": "UTC", "counters": {")" + tag +
                           R"(": {"start": 1}}, "pens": {"p": {"speed_mm_s": 1000}},
      "objects": [{"name": "serial", "template": ")" + tag + R"( {)" + tag + R"(}", "height_mm": 1}]})";
  const JobFile job = parse_job(text, tag + ".json");
  const JobFonts fonts(job);
  MarkContext ctx;
  ctx.station = "matrix";
  ctx.job = job.source;
  ctx.job_sha256 = sha256_hex(text);
  ctx.now = SystemClock().now();
  FaultRow row{c, "", ""};
  std::optional<std::int64_t> mark_id;
  {
    // The counter is created before the fault is armed: creating it is a write of the same
    // step (allocate), and the matrix is about the part.
    open(StoreSettings{})->create_missing(job.used_counters(), job.shifts, ctx);
  }
  {
    StoreSettings settings;
    settings.retry = {3, 20, 100};
    settings.journal_dir = journal_dir;
    settings.fault = StoreFaultPlan{c.step, c.kind, 1, c.attempts};
    std::unique_ptr<SerialStore> store = open(settings);
    store->start_station(ctx);
    SimScanner sim(simulator_options(object_spec(job, job.objects.front(), "", fonts)));
    PartRunner runner(job, fonts, {}, sim, *store, ctx);
    PartOptions options;
    options.job.virtual_time = true;
    try {
      const PartResult p = runner.mark_next(SystemClock().now(), options);
      mark_id = p.mark_id;
      EXPECT_EQ(p.outcome, JobOutcome::done);
      row.during = std::string(to_string(p.outcome)) + ", recorded in the " +
                   (p.recorded.stored ? "store (attempt " + std::to_string(p.recorded.attempts) + ")"
                    : p.recorded.journaled ? std::string("journal")
                                           : std::string("nowhere: ") + p.record_error);
      EXPECT_TRUE(p.recorded.stored || p.recorded.journaled) << p.record_error;
      if (!p.recorded.stored) {
        EXPECT_FALSE(p.recorded.error.empty());
      }
    } catch (const std::exception& e) {
      EXPECT_EQ(sim.samples(), 0u) << "a refused part reached the device";
      const bool store_error = dynamic_cast<const StoreError*>(&e) != nullptr;
      row.during = std::string("refused before the laser (") +
                   (store_error ? std::string(to_string(dynamic_cast<const StoreError&>(e).kind())) : "?") + ")";
      EXPECT_TRUE(store_error) << e.what();
    }
  }
  // The next start: no fault; the journal replayed, open rows closed.
  StoreSettings settings;
  settings.journal_dir = journal_dir;
  std::unique_ptr<SerialStore> store = open(settings);
  ctx.now = SystemClock().now();
  const StationStart started = store->start_station(ctx);
  std::size_t consumed = 0;
  for (const auto& [issue, id] : store->issues(tag)) consumed += id > 0;
  if (!mark_id) {
    EXPECT_EQ(consumed, 0u) << "a refused part consumed a number";
    row.after = "nothing consumed, nothing logged";
    return row;
  }
  const std::optional<AuditRow> r = [&]() -> std::optional<AuditRow> {
    for (AuditRow& a : store->log())
      if (a.id == *mark_id) return a;
    return std::nullopt;
  }();
  EXPECT_TRUE(r && r->outcome) << "row left open";
  if (!r || !r->outcome) return row;
  EXPECT_EQ(r->outcome->outcome, Outcome::done) << "a part marked in full logged " << to_string(r->outcome->outcome);
  EXPECT_GT(r->outcome->figures.value("samples", 0), 0) << "the figures were lost";
  const bool replayed = std::find(started.replayed.begin(), started.replayed.end(), *mark_id) != started.replayed.end();
  row.after = std::string(to_string(r->outcome->outcome)) + (replayed ? " (replayed from the journal)" : "");
  return row;
}

inline void print_fault_matrix(const char* store, const std::vector<FaultRow>& rows) {
  std::printf("[fault matrix] %s: step × fault × failing attempts (of 3) → the part, then its row after the "
              "next start\n",
              store);
  for (const FaultRow& r : rows)
    std::printf("[fault matrix] | %-8s | %-7s | %-5s | %-45s | %s |\n", std::string(to_string(r.c.step)).c_str(),
                std::string(to_string(r.c.kind)).c_str(), r.c.attempts ? std::to_string(r.c.attempts).c_str() : "all",
                r.during.c_str(), r.after.c_str());
}

}  // namespace mark::test
