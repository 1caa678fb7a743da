// A serial can never come back. Whatever happens to the counters — a wrap at the limit, a reset
// at midnight without a date in the text, a copied job, a renamed counter — a part whose text
// (in an object carrying a serial field) was marked before is refused before the laser fires,
// naming the earlier row, and consumes nothing. A counter exists only once created. A clock
// stepped back across any kind of reset neither blocks a counter nor repeats a value: periods
// only move forward, the step is noted in the audit row, and the part is dated in its period.
// A re-mark is the one exception, and a second re-mark of a done part needs a reason.
#include <gtest/gtest.h>

#include <date/date.h>

#include <set>

#include "marker/job/sim_evaluator.hpp"
#include "marker/production/part_run.hpp"
#include "marker/production/text_repeats.hpp"
#include "marker/store/digest.hpp"
#include "store_test_support.hpp"
#include "tests/marker/vars/at_utc.hpp"

namespace mark {
namespace {

using namespace std::chrono;

using test::at_utc;

std::string job_text(const std::string& counter, const std::string& rules, const std::string& templ) {
  return R"({"format": "marker-job/1", "time_zone": "UTC", "counters": {")" + counter + R"(": {)" + rules +
         R"(}}, "shifts": [{"code": "M", "start": "06:00"}, {"code": "N", "start": "22:00"}],
         "pens": {"p": {"speed_mm_s": 1000}},
         "objects": [{"name": "serial", "template": ")" + templ + R"(", "height_mm": 1}]})";
}

// One station marking one job file (or a copy of it) on the simulated scanner.
struct Line {
  std::filesystem::path dir = test::fresh_store_dir("guard");
  std::unique_ptr<SerialStore> store = open_store((dir / "station.sqlite").string(), StoreAccess::create);

  struct Run {
    JobFile job;
    JobFonts fonts;
    SimScanner sim;
    PartRunner runner;
    Run(const std::string& text, const std::string& file, SerialStore& store)
        : job(parse_job(text, file)),
          fonts(job),
          sim(simulator_options(object_spec(job, job.objects.front(), "", fonts))),
          runner(job, fonts, {}, sim, store, context(text, file)) {}
    static MarkContext context(const std::string& text, const std::string& file) {
      MarkContext c;
      c.station = "s1";
      c.job = file;
      c.job_sha256 = sha256_hex(text);
      return c;
    }
    PartResult mark(SysTime now) {
      PartOptions o;
      o.job.virtual_time = true;
      return runner.mark_next(now, o);
    }
  };

  Line() { store->start_station(Run::context("", "")); }
  ~Line() {
    store.reset();
    std::filesystem::remove_all(dir);
  }
  std::unique_ptr<Run> run(const std::string& text, const std::string& file = "part.json") {
    auto r = std::make_unique<Run>(text, file, *store);
    store->create_missing(r->job.used_counters(), r->job.shifts, Run::context(text, file));
    return r;
  }
  std::size_t issued(const std::string& counter) { return store->issues(counter).size(); }
};

// The part is refused before anything reaches the device, naming the row that marked the text.
void expect_refused(Line::Run& run, SysTime now, std::int64_t earlier_row, const std::string& text) {
  const std::uint64_t samples = run.sim.samples();
  try {
    run.mark(now);
    FAIL() << "a repeated text was marked";
  } catch (const PartRefused& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("would mark \"" + text + "\", which row " + std::to_string(earlier_row) + " ("),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("a re-mark of that part: --remark " + std::to_string(earlier_row)), std::string::npos) << what;
  }
  EXPECT_EQ(run.sim.samples(), samples) << "the laser fired";
}

TEST(TextGuard, AWrapWouldRepeatATextAndIsRefused) {
  Line line;
  auto run = line.run(job_text("sn", R"("start": 1, "limit": 3, "at_limit": "wrap")", "SN {sn}"));
  const SysTime t = at_utc(2026, 3, 5, 9, 0);
  std::vector<std::int64_t> ids;
  for (int i = 0; i < 3; ++i) ids.push_back(run->mark(t).mark_id);
  expect_refused(*run, t, ids[0], "SN 1");
  EXPECT_EQ(line.issued("sn"), 3u) << "the refused part consumed a number";
  // job check saw it coming.
  const auto warnings = text_repeat_warnings(run->job);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("counter \"sn\" wraps to 1 after 3"), std::string::npos) << warnings[0];
}

TEST(TextGuard, AResetWithoutADateWouldRepeatATextAndIsRefused) {
  Line line;
  auto run = line.run(job_text("sn", R"("reset": "midnight")", "SN {sn}"));
  const std::int64_t first = run->mark(at_utc(2026, 3, 5, 9, 0)).mark_id;
  run->mark(at_utc(2026, 3, 5, 9, 1));
  expect_refused(*run, at_utc(2026, 3, 6, 9, 0), first, "SN 1");
  EXPECT_EQ(line.issued("sn"), 2u);
  const auto warnings = text_repeat_warnings(run->job);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "part.json: objects[0] \"serial\": counter \"sn\" restarts every midnight and no date field "
                         "names the day (and year): its texts repeat, and the store refuses a part whose text was "
                         "marked before (add {date:%y%j}, or a date format naming day and year)");
  // With the day in the text the reset makes new texts, and job check is content.
  auto dated = line.run(job_text("sd", R"("reset": "midnight")", "{date:%y%j}-{sd}"), "dated.json");
  EXPECT_TRUE(text_repeat_warnings(dated->job).empty());
  EXPECT_EQ(dated->mark(at_utc(2026, 3, 5, 9, 0)).text(), "26064-1");
  EXPECT_EQ(dated->mark(at_utc(2026, 3, 6, 9, 0)).text(), "26065-1");
}

TEST(TextGuard, ACopiedJobMarksIntoTheSameStoreAndContinues) {
  Line line;
  const std::string text = job_text("sn", R"("start": 1)", "SN {sn}");
  auto run = line.run(text, "part.json");
  run->mark(at_utc(2026, 3, 5, 9, 0));
  run->mark(at_utc(2026, 3, 5, 9, 0));
  // part-v2.json: the same counter of the same (station's) store — never SN 1 again.
  auto copy = line.run(text, "part-v2.json");
  EXPECT_EQ(copy->mark(at_utc(2026, 3, 5, 9, 0)).text(), "SN 3");
  EXPECT_EQ(line.issued("sn"), 3u);
}

TEST(TextGuard, ARenamedCounterMustBeCreatedAndThenRepeatsNoText) {
  Line line;
  auto run = line.run(job_text("serial", R"("start": 1)", "SN {serial}"));
  const std::int64_t first = run->mark(at_utc(2026, 3, 5, 9, 0)).mark_id;
  // {serial} → {sn}: the store does not know "sn", so the part is refused, not numbered from 1.
  const std::string renamed = job_text("sn", R"("start": 1)", "SN {sn}");
  Line::Run bare(renamed, "part.json", *line.store);
  try {
    bare.mark(at_utc(2026, 3, 5, 9, 0));
    FAIL();
  } catch (const PartRefused& e) {
    EXPECT_NE(std::string(e.what()).find("counter \"sn\" is not in the serial store sqlite:"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("create it with `marker serial create sn [--start N]`"), std::string::npos);
  }
  EXPECT_EQ(bare.sim.samples(), 0u);
  // Created anyway (at 1): the text it would mark again is refused.
  auto created = line.run(renamed);
  expect_refused(*created, at_utc(2026, 3, 5, 9, 0), first, "SN 1");
  EXPECT_EQ(line.issued("sn"), 0u);
}

// The clock steps back and forward across every kind of reset: no part is blocked, no value
// issued twice, no text repeated; every step back is noted in its audit row.
TEST(TextGuard, ClockStepsAcrossEveryKindOfResetNeitherBlockNorRepeat) {
  struct Case {
    const char* rules;
    const char* templ;
    std::vector<SysTime> clock;
  };
  const std::vector<Case> cases = {
      // Midnight: over midnight, back 5 minutes, forward, a day skipped, back a whole day.
      {R"("reset": "midnight")", "{date:%Y-%m-%d}/{sn}",
       {at_utc(2026, 3, 5, 23, 50), at_utc(2026, 3, 6, 0, 10), at_utc(2026, 3, 5, 23, 55),
        at_utc(2026, 3, 5, 23, 59), at_utc(2026, 3, 6, 0, 20), at_utc(2026, 3, 8, 0, 30), at_utc(2026, 3, 7, 9, 0),
        at_utc(2026, 3, 8, 1, 0)}},
      // Shift starts (M 06:00, N 22:00): back across 22:00 and across 06:00 (into the night before).
      {R"("reset": "shift")", "{date:%Y-%m-%d}{shift}{sn}",
       {at_utc(2026, 3, 5, 21, 58), at_utc(2026, 3, 5, 22, 1), at_utc(2026, 3, 5, 21, 59), at_utc(2026, 3, 6, 6, 5),
        at_utc(2026, 3, 6, 5, 55), at_utc(2026, 3, 6, 6, 10), at_utc(2026, 3, 5, 12, 0)}},
      // No reset, with a wrap: the clock does not matter, the cycle moves on.
      {R"("limit": 2, "at_limit": "wrap")", "{date:%Y-%m-%d}/{sn}",
       {at_utc(2026, 3, 5, 9, 0), at_utc(2026, 3, 5, 9, 1), at_utc(2026, 3, 4, 9, 0), at_utc(2026, 3, 6, 9, 0)}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.rules);
    Line line;
    auto run = line.run(job_text("sn", c.rules, c.templ));
    std::set<std::string> texts;
    int noted = 0;
    for (SysTime t : c.clock) {
      PartResult p;
      ASSERT_NO_THROW(p = run->mark(t)) << "blocked at " << date::format("%F %R", t);
      EXPECT_EQ(p.outcome, JobOutcome::done);
      EXPECT_TRUE(texts.insert(p.text()).second) << "text repeated: " << p.text();
      if (!p.note.empty()) {
        ++noted;
        EXPECT_NE(p.note.find("periods only move forward"), std::string::npos) << p.note;
      }
    }
    // Every value once per (period, cycle), the log agreeing with the parts.
    const std::vector<std::int64_t> values = test::check_store_consistent(*line.store, "sn");
    EXPECT_EQ(values.size(), c.clock.size());
    std::set<std::tuple<std::string, std::int64_t, std::int64_t>> keys;
    std::string last_period;
    int noted_rows = 0;
    for (const AuditRow& r : line.store->log()) {
      if (r.mark.kind != AuditKind::mark) continue;
      ASSERT_EQ(r.issues.size(), 1u);
      const Issue& i = r.issues[0];
      EXPECT_TRUE(keys.insert({i.period, i.cycle, i.value}).second);
      if (!last_period.empty()) {
        EXPECT_GE(i.period, last_period) << "a period went back";
      }
      last_period = i.period;
      noted_rows += !r.mark.note.empty();
    }
    EXPECT_EQ(noted_rows, noted);
    if (std::string(c.rules).find("reset") != std::string::npos) {
      EXPECT_GT(noted, 0);
    }
  }
}

TEST(TextGuard, ASecondRemarkOfADonePartNeedsAReason) {
  Line line;
  auto run = line.run(job_text("sn", R"("start": 1)", "SN {sn}"));
  const PartResult first = run->mark(at_utc(2026, 3, 5, 9, 0));
  PartOptions o;
  o.job.virtual_time = true;
  const PartResult again = run->runner.remark(first.mark_id, at_utc(2026, 3, 5, 9, 1), o);
  EXPECT_EQ(again.remark_of, first.mark_id);
  EXPECT_EQ(again.text(), "SN 1");
  try {
    run->runner.remark(again.mark_id, at_utc(2026, 3, 5, 9, 2), o);  // a re-mark of the re-mark: the same part
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--remark " + std::to_string(again.mark_id) + ": part " +
                                         std::to_string(first.mark_id) +
                                         " (\"SN 1\") was marked done and re-marked already (row " +
                                         std::to_string(again.mark_id) +
                                         "); a further re-mark needs --reason TEXT, which the audit log keeps");
  }
  o.remark_reason = "customer return 4711: unreadable";
  const PartResult third = run->runner.remark(again.mark_id, at_utc(2026, 3, 5, 9, 3), o);
  EXPECT_EQ(third.remark_of, first.mark_id);
  const AuditRow row = line.store->log().back();
  EXPECT_EQ(row.mark.reason, "customer return 4711: unreadable");
  EXPECT_EQ(row.mark.remark_of, first.mark_id);
  ASSERT_EQ(row.issues.size(), 1u);  // the original's value, period and cycle
  EXPECT_EQ(row.issues[0].value, 1);
  EXPECT_EQ(line.issued("sn"), 1u) << "re-marks consume nothing";
}

}  // namespace
}  // namespace mark
