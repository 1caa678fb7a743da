// The fault-injection matrix on the SQLite store: a second connection holding the write lock,
// the disk reporting full, the disk failing (through the fault VFS, so SQLite's own error paths
// run) — at the allocation and at the outcome, once and for good. A part refused before the
// laser consumed nothing; a part marked in full is logged done, straight away, after a retry,
// or from the outcome journal at the next start.
#include "fault_matrix.hpp"

#include "marker/store/open_store.hpp"
#include "store_test_support.hpp"

namespace mark {
namespace {

TEST(StoreFaults, SqliteMatrix) {
  std::vector<test::FaultRow> rows;
  int n = 0;
  for (StoreStep step : {StoreStep::allocate, StoreStep::outcome}) {
    for (StoreFaultKind kind : {StoreFaultKind::locked, StoreFaultKind::full, StoreFaultKind::io}) {
      for (int attempts : {1, 0}) {
        const test::FaultCase c{step, kind, attempts};
        SCOPED_TRACE(std::string(to_string(step)) + " " + std::string(to_string(kind)) + " " + std::to_string(attempts));
        const auto dir = test::fresh_store_dir("faults-" + std::to_string(n++));
        const std::string path = (dir / "station.sqlite").string();
        StoreOptions options;
        options.wait_ms = 100;
        options.fault_injection = true;
        rows.push_back(test::run_fault_case(
            [&](StoreSettings s) { return open_store(path, StoreAccess::create, std::move(s), options); }, c,
            (dir / "journal").string(), "sn"));
        std::filesystem::remove_all(dir);
      }
    }
  }
  test::print_fault_matrix("SQLite", rows);
  // What the matrix must show: a lock waited out on a retry, a persistent fault at the
  // allocation refused, at the outcome kept in the journal and replayed.
  EXPECT_EQ(rows[0].during.substr(0, 4), "done");                            // allocate, locked once
  EXPECT_EQ(rows[1].during.substr(0, 7), "refused");                         // allocate, locked always
  EXPECT_EQ(rows[8].during, "done, recorded in the store (attempt 2)");      // outcome, full once
  EXPECT_EQ(rows[9].during.substr(0, 28), "done, recorded in the journa");   // outcome, full always
  EXPECT_EQ(rows[9].after, "done (replayed from the journal)");
}

TEST(StoreFaults, APartAfterAJournaledOutcomeReplaysItFirst) {
  const auto dir = test::fresh_store_dir("faults-next");
  const std::string path = (dir / "station.sqlite").string();
  StoreOptions options;
  options.wait_ms = 50;
  options.fault_injection = true;
  StoreSettings settings;
  settings.retry = {2, 10, 10};
  settings.journal_dir = (dir / "journal").string();
  settings.fault = StoreFaultPlan{StoreStep::outcome, StoreFaultKind::locked, 1, 0};
  auto store = open_store(path, StoreAccess::create, settings, options);
  const std::map<std::string, CounterSpec> counters{{"sn", test::plain_counter()}};
  test::create_counters(*store, counters);
  MarkContext ctx;
  ctx.station = "s1";
  store->start_station(ctx);
  const Allocation a = store->allocate(counters, ShiftTable{}, ctx, test::render_sn());
  OutcomeRecord done;
  done.time_utc = format_utc(ctx.now);
  done.figures = {{"samples", 7531}};
  const OutcomeWrite w = store->record_outcome(a.mark_id, done);
  EXPECT_FALSE(w.stored);
  EXPECT_TRUE(w.journaled);
  EXPECT_EQ(w.attempts, 2);
  EXPECT_NE(w.error.find("locked by another process for more than 50 ms"), std::string::npos) << w.error;
  EXPECT_FALSE(store->log().back().outcome);
  // The next part's allocation takes the journal's outcome into the store first.
  store->allocate(counters, ShiftTable{}, ctx, test::render_sn());
  const std::vector<AuditRow> log = store->log();
  ASSERT_TRUE(log[1].outcome);
  EXPECT_EQ(log[1].outcome->outcome, Outcome::done);
  EXPECT_EQ(log[1].outcome->figures.at("samples"), 7531);
  EXPECT_TRUE(store->journal()->empty());
  store.reset();
  std::filesystem::remove_all(dir);
}

TEST(StoreFaults, NeitherStoreNorJournalIsOneErrorAndTheNextStartClosesTheRow) {
  const auto dir = test::fresh_store_dir("faults-none");
  const std::string path = (dir / "station.sqlite").string();
  StoreOptions options;
  options.wait_ms = 20;
  StoreSettings settings;
  settings.retry = {1, 0, 0};
  settings.fault = StoreFaultPlan{StoreStep::outcome, StoreFaultKind::locked, 1, 0};  // and no journal
  const std::map<std::string, CounterSpec> counters{{"sn", test::plain_counter()}};
  MarkContext ctx;
  ctx.station = "s1";
  std::int64_t id = 0;
  {
    auto store = open_store(path, StoreAccess::create, settings, options);
    test::create_counters(*store, counters);
    store->start_station(ctx);
    id = store->allocate(counters, ShiftTable{}, ctx, test::render_sn()).mark_id;
    try {
      store->record_outcome(id, OutcomeRecord{});
      FAIL();
    } catch (const StoreError& e) {
      EXPECT_EQ(e.kind(), StoreErrorKind::busy);
      EXPECT_NE(std::string(e.what()).find("the outcome of row 2 (done) was not recorded: "), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("no outcome journal — the station's next start records the row aborted"),
                std::string::npos);
    }
  }
  auto store = open_store(path, StoreAccess::existing);
  EXPECT_EQ(store->start_station(ctx).closed, (std::vector<std::int64_t>{id}));
  store.reset();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mark
