// The SQLite serial store: allocation before marking, outcomes, void numbers, re-marks, set and
// reserve, recovery after a dead process, and the append-only audit log.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <date/date.h>

#include "marker/store/digest.hpp"
#include "marker/store/utc_time.hpp"
#include "store_test_support.hpp"

namespace mark {
namespace {

using namespace std::chrono;
using test::check_store_consistent;
using test::fresh_store_dir;
using test::plain_counter;
using test::render_sn;

MarkContext context(const std::string& station = "st1") {
  MarkContext c;
  c.station = station;
  c.job = "job.json";
  c.job_sha256 = sha256_hex("{}");
  c.now = SysTime{date::sys_days{date::year{2026} / 3 / 5}} + hours{9};
  return c;
}

struct StoreFixture : testing::Test {
  std::filesystem::path dir = fresh_store_dir("unit");
  std::string path = (dir / "job.serials.sqlite").string();
  std::unique_ptr<SerialStore> store = open_store(path, StoreAccess::create);
  std::map<std::string, CounterSpec> counters{{"sn", plain_counter()}};
  ShiftTable shifts;
  void SetUp() override { test::create_counters(*store, counters); }
  // The audit rows of parts (the counters' creation rows aside).
  std::vector<AuditRow> parts() {
    std::vector<AuditRow> rows;
    for (AuditRow& r : store->log())
      if (r.mark.kind != AuditKind::create) rows.push_back(std::move(r));
    return rows;
  }
  void TearDown() override {
    store.reset();
    std::filesystem::remove_all(dir);
  }
};

TEST(Digest, Sha256OfKnownInputs) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(UtcTime, FormatsAndParsesInstants) {
  const SysTime t = SysTime{date::sys_days{date::year{2026} / 3 / 5}} + hours{9} + minutes{41} +
                    microseconds{123456};
  EXPECT_EQ(format_utc(t), "2026-03-05T09:41:00.123456Z");
  EXPECT_EQ(parse_since("2026-03-05T09:41:00.123456Z", t), t);
  EXPECT_EQ(parse_since("2026-03-05 09:41", t), t - microseconds{123456});
  EXPECT_EQ(parse_since("2026-03-05", t), SysTime{date::sys_days{date::year{2026} / 3 / 5}});
  EXPECT_EQ(parse_since("2h", t), t - hours{2});
  EXPECT_EQ(parse_since("7d", t), t - hours{7 * 24});
  EXPECT_FALSE(parse_since("2026-02-30", t));
  EXPECT_FALSE(parse_since("yesterday", t));
  EXPECT_FALSE(parse_since("2026-03-05T25:00", t));
}

TEST_F(StoreFixture, AllocatesConsecutiveNumbersWithAuditRows) {
  const MarkContext ctx = context();
  for (int i = 0; i < 3; ++i) {
    const Allocation a = store->allocate(counters, shifts, ctx, render_sn());
    EXPECT_EQ(a.serials.at("sn"), i + 1);
    EXPECT_EQ(a.objects.at(0).text, "SN " + std::to_string(i + 1));
    OutcomeRecord o;
    o.time_utc = format_utc(ctx.now);
    o.figures = {{"mark_time_s", 0.02}};
    store->record_outcome(a.mark_id, o);
  }
  const std::vector<AuditRow> log = parts();
  ASSERT_EQ(log.size(), 3u);
  EXPECT_EQ(log[1].text(), "SN 2");
  EXPECT_EQ(log[1].mark.station, "st1");
  EXPECT_EQ(log[1].mark.job_sha256, sha256_hex("{}"));
  ASSERT_TRUE(log[1].outcome);
  EXPECT_EQ(log[1].outcome->outcome, Outcome::done);
  EXPECT_DOUBLE_EQ(log[1].outcome->figures.at("mark_time_s").get<double>(), 0.02);
  EXPECT_EQ(check_store_consistent(*store, "sn"), (std::vector<std::int64_t>{1, 2, 3}));
}

TEST_F(StoreFixture, AbortedNumbersAreVoidAndNeverIssuedAgain) {
  const MarkContext ctx = context();
  const Allocation a = store->allocate(counters, shifts, ctx, render_sn());
  OutcomeRecord aborted;
  aborted.outcome = Outcome::aborted;
  aborted.message = "Ctrl-C";
  store->record_outcome(a.mark_id, aborted);
  const Allocation b = store->allocate(counters, shifts, ctx, render_sn());
  EXPECT_EQ(b.serials.at("sn"), 2);
  // A second outcome for the same row is refused: outcomes are written once.
  EXPECT_THROW(store->record_outcome(a.mark_id, OutcomeRecord{}), StoreError);
}

TEST_F(StoreFixture, RenderFailureConsumesNothing) {
  const MarkContext ctx = context();
  EXPECT_THROW(store->allocate(counters, shifts, ctx,
                               [](const auto&) -> std::vector<ObjectText> {
                                 throw InputError("{var:lot} has no value");
                               }),
               InputError);
  EXPECT_EQ(store->allocate(counters, shifts, ctx, render_sn()).serials.at("sn"), 1);
  EXPECT_EQ(parts().size(), 1u);
}

TEST_F(StoreFixture, StopAtLimitConsumesNothing) {
  counters["sn"].limit = 2;
  const MarkContext ctx = context();
  store->allocate(counters, shifts, ctx, render_sn());
  store->allocate(counters, shifts, ctx, render_sn());
  EXPECT_THROW(store->allocate(counters, shifts, ctx, render_sn()), SerialLimitError);
  EXPECT_EQ(parts().size(), 2u);
}

TEST_F(StoreFixture, SeveralCountersPerPartAndMarksPerSerial) {
  counters["lot"] = plain_counter("lot", 500, -10);
  counters["lot"].marks_per_serial = 2;
  test::create_counters(*store, counters);
  const MarkContext ctx = context();
  std::vector<std::pair<std::int64_t, std::int64_t>> seen;
  for (int i = 0; i < 4; ++i) {
    const Allocation a = store->allocate(counters, shifts, ctx, render_sn());
    seen.emplace_back(a.serials.at("sn"), a.serials.at("lot"));
  }
  EXPECT_EQ(seen, (std::vector<std::pair<std::int64_t, std::int64_t>>{
                      {1, 500}, {2, 500}, {3, 490}, {4, 490}}));
}

TEST_F(StoreFixture, CountersContinueAcrossReopening) {
  const MarkContext ctx = context();
  store->allocate(counters, shifts, ctx, render_sn());
  store.reset();
  store = open_store(path, StoreAccess::existing);
  EXPECT_EQ(store->allocate(counters, shifts, ctx, render_sn()).serials.at("sn"), 2);
}

TEST_F(StoreFixture, MidnightResetRestartsTheCounterAndKeepsOldIssues) {
  counters["sn"].reset = ResetRule::midnight;
  MarkContext ctx = context();
  // The day in the text, as a counter that restarts at midnight needs (job check warns
  // otherwise): the restarted values make new texts.
  const RenderObjects dated = [&](const std::map<std::string, std::int64_t>& serials) {
    return std::vector<ObjectText>{{"serial", format_utc(ctx.now).substr(0, 10) + " " + std::to_string(serials.at("sn")), true}};
  };
  store->allocate(counters, shifts, ctx, dated);
  store->allocate(counters, shifts, ctx, dated);
  ctx.now += hours{24};
  EXPECT_EQ(store->allocate(counters, shifts, ctx, dated).serials.at("sn"), 1);
  const auto issues = store->issues("sn");
  ASSERT_EQ(issues.size(), 3u);
  EXPECT_EQ(issues[2].first.period, "2026-03-06");
}

TEST_F(StoreFixture, RemarkLinksTheFirstMarkAndConsumesNoNumber) {
  const MarkContext ctx = context();
  const Allocation a = store->allocate(counters, shifts, ctx, render_sn());
  OutcomeRecord failed;
  failed.outcome = Outcome::failed;
  store->record_outcome(a.mark_id, failed);
  const Allocation again = store->remark(a.mark_id, ctx);
  EXPECT_EQ(again.serials.at("sn"), 1);
  EXPECT_EQ(again.objects.at(0).text, "SN 1");
  const auto row = store->log().back();
  EXPECT_EQ(row.mark.kind, AuditKind::remark);
  EXPECT_EQ(row.mark.remark_of, a.mark_id);
  EXPECT_EQ(store->allocate(counters, shifts, ctx, render_sn()).serials.at("sn"), 2);
  EXPECT_THROW(store->remark(999, ctx), InputError);
  MarkContext other = ctx;
  other.job_sha256 = sha256_hex("another job");
  EXPECT_THROW(store->remark(a.mark_id, other), InputError);
}

TEST_F(StoreFixture, SetBelowAnIssuedValueIsRefused) {
  const MarkContext ctx = context();
  for (int i = 0; i < 5; ++i) store->allocate(counters, shifts, ctx, render_sn());
  try {
    store->set(counters["sn"], 3, shifts, ctx);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "serial set sn 3: refused, 5 was already issued in this period (a number is "
                 "never issued twice); the next value is at least 6");
  }
  EXPECT_THROW(store->set(counters["sn"], 5, shifts, ctx), InputError);
  store->set(counters["sn"], 1000, shifts, ctx);
  const CounterStatus st = store->status("sn", &counters["sn"], shifts, ctx.now);
  EXPECT_EQ(st.next, 1000);
  EXPECT_EQ(st.highest_issued, 5);
  EXPECT_EQ(store->allocate(counters, shifts, ctx, render_sn()).serials.at("sn"), 1000);
  EXPECT_EQ(store->log().back().mark.serials.at("sn"), 1000);
}

TEST_F(StoreFixture, ReserveIssuesValuesWithOneRowEach) {
  const MarkContext ctx = context();
  const std::vector<Issue> r = store->reserve(counters["sn"], 3, shifts, ctx);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[2].value, 3);
  EXPECT_EQ(store->allocate(counters, shifts, ctx, render_sn()).serials.at("sn"), 4);
  EXPECT_EQ(check_store_consistent(*store, "sn"), (std::vector<std::int64_t>{1, 2, 3, 4}));
  EXPECT_EQ(parts()[0].outcome->outcome, Outcome::reserved);
}

TEST_F(StoreFixture, StartStationClosesRowsADeadProcessLeftOpen) {
  const MarkContext ctx = context();
  const Allocation a = store->allocate(counters, shifts, ctx, render_sn());
  store.reset();  // the process "dies" before recording the outcome
  store = open_store(path, StoreAccess::existing);
  EXPECT_EQ(store->start_station(ctx).closed, (std::vector<std::int64_t>{a.mark_id}));
  const AuditRow row = parts().at(0);
  ASSERT_TRUE(row.outcome);
  EXPECT_EQ(row.outcome->outcome, Outcome::aborted);
  EXPECT_EQ(row.outcome->message.substr(0, 12), "interrupted:");
  EXPECT_EQ(store->allocate(counters, shifts, ctx, render_sn()).serials.at("sn"), 2);
}

TEST_F(StoreFixture, OneProcessPerStation) {
  store->start_station(context("A"));
  auto second = open_store(path, StoreAccess::existing);
  EXPECT_THROW(second->start_station(context("A")), StoreError);
  EXPECT_NO_THROW(second->start_station(context("B")));
}

TEST_F(StoreFixture, TheAuditLogIsAppendOnly) {
  store->allocate(counters, shifts, context(), render_sn());
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  for (const char* sql : {"UPDATE marks SET station = 'x'", "DELETE FROM marks",
                          "DELETE FROM issues", "UPDATE issues SET value = 7"}) {
    char* err = nullptr;
    EXPECT_NE(sqlite3_exec(db, sql, nullptr, nullptr, &err), SQLITE_OK) << sql;
    EXPECT_NE(std::string(err ? err : "").find("append-only"), std::string::npos) << sql;
    sqlite3_free(err);
  }
  // And the key refuses a second issue of a value, whatever writes it.
  char* err = nullptr;
  EXPECT_NE(sqlite3_exec(db, "INSERT INTO issues VALUES('sn', '', 0, 1, 0, 1)", nullptr, nullptr, &err),
            SQLITE_OK);
  sqlite3_free(err);
  sqlite3_close(db);
}

// A store of a format this program does not know (a newer program's) is refused naming the
// store, its format and the formats read (store_format.hpp, both backends), and left as it was.
TEST_F(StoreFixture, AStoreOfAnUnknownFormatIsRefusedAndLeftAsItWas) {
  store.reset();
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "UPDATE meta SET value = 'marker-store/9' WHERE key = 'format'", nullptr, nullptr, nullptr),
            SQLITE_OK)
      << sqlite3_errmsg(db);
  sqlite3_close(db);
  try {
    auto again = open_store(path, StoreAccess::existing);
    again->start_station(context());
    FAIL() << "a store of format marker-store/9 was opened";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("has format 'marker-store/9', this program reads marker-store/1 and "
                                         "marker-store/2"),
              std::string::npos)
        << e.what();
  }
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* q = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT value FROM meta WHERE key = 'format'", -1, &q, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(q), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(q, 0)), "marker-store/9");
  sqlite3_finalize(q);
  sqlite3_close(db);
}

TEST_F(StoreFixture, MissingStoreIsAnErrorWhenNotCreating) {
  EXPECT_THROW(open_store((dir / "nope.sqlite").string(), StoreAccess::existing), StoreError);
  EXPECT_FALSE(std::filesystem::exists(dir / "nope.sqlite"));
}

TEST(StoreLocation, UrlsAndTheOldStoreBesideAJob) {
  EXPECT_EQ(job_side_store_path("/lines/3/bracket.json"), "/lines/3/bracket.serials.sqlite");
  EXPECT_TRUE(is_postgres_url("postgresql://line3@db/serials"));
  EXPECT_FALSE(is_postgres_url("/tmp/postgresql.sqlite"));
}

}  // namespace
}  // namespace mark
