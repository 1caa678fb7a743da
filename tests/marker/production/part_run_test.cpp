// A production part from allocation to its audit row (PartRunner): consecutive serials, every
// object with its own pen on the device, the outcome and figures recorded; a part whose second
// object is aborted or whose device fails is recorded so and its number is void; a refused part
// consumes nothing; re-marks link their row.
#include <gtest/gtest.h>

#include "base/error.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "marker/production/part_run.hpp"
#include "marker/store/digest.hpp"
#include "marker/store/open_store.hpp"
#include "tests/marker/recording_command_device.hpp"
#include "tests/marker/store/store_test_support.hpp"

namespace mark {
namespace {

// Two objects: a short serial with a full-power pen, a longer lot line with a half-power pen at
// a lower frequency.
constexpr const char* kPartRunJob = R"({
  "format": "marker-job/1",
  "head": "SL10",
  "time_zone": "UTC",
  "variables": {"lot": "A00"},
  "counters": {"serial": {"start": 41, "width": 6}},
  "pens": {
    "fine": {"speed_mm_s": 800, "power_pct": 100, "frequency_khz": 40},
    "half": {"speed_mm_s": 600, "power_pct": 50, "frequency_khz": 20}
  },
  "objects": [
    {"name": "serial", "pen": "fine", "template": "SN {serial}", "height_mm": 3, "x_mm": -20, "y_mm": 3},
    {"name": "lot", "pen": "half", "template": "LOT {var:lot} BATCH 2026-11-23", "height_mm": 2, "x_mm": -20, "y_mm": -3}
  ]
})";

struct PartStation {
  std::filesystem::path dir = test::fresh_store_dir("part-run");
  JobFile job;
  JobFonts fonts;
  std::unique_ptr<SerialStore> store;
  MarkContext context;

  explicit PartStation(const std::string& text = kPartRunJob)
      : job(parse_job(text, "line.json")),
        fonts(job),
        store(open_store((dir / "line.serials.sqlite").string(), StoreAccess::create)) {
    context.station = "s1";
    context.job = "line.json";
    context.job_sha256 = sha256_hex(text);
    context.now = SystemClock().now();
    store->start_station(context);
    test::create_counters(*store, job.used_counters());
  }
  ~PartStation() {
    store.reset();
    std::filesystem::remove_all(dir);
  }
  // The audit rows of parts (the counters' creation rows aside).
  std::vector<AuditRow> parts() {
    std::vector<AuditRow> rows;
    for (AuditRow& r : store->log())
      if (r.mark.kind != AuditKind::create) rows.push_back(std::move(r));
    return rows;
  }
  SimScannerOptions sim_options() const {
    return simulator_options(object_spec(job, job.objects.front(), "", fonts));
  }
  PartRunner runner(Device& device, std::map<std::string, std::string> vars = {{"lot", "A17"}}) {
    return PartRunner(job, fonts, std::move(vars), device, *store, context);
  }
};

// `evaluator`: what tells the quality figures (the simulated scanner's); none: no figures.
PartOptions virtual_time(MarkEvaluator* evaluator = nullptr) {
  PartOptions o;
  o.job.virtual_time = true;
  o.job.evaluator = evaluator;
  return o;
}

double figure(const JobResult& r, const std::string& name) {
  for (const auto& [k, v] : r.device.figures)
    if (k == name) return v;
  ADD_FAILURE() << "no device figure " << name;
  return 0;
}

TEST(PartRun, ThreePartsTakeConsecutiveSerialsWithEveryObjectsPen) {
  PartStation st;
  SimScanner sim(st.sim_options());
  SimEvaluator evaluator(sim);
  PartRunner runner = st.runner(sim);
  std::vector<PartPhase> phases;
  PartOptions options = virtual_time(&evaluator);
  options.phase = [&](PartPhase p, const auto&) { phases.push_back(p); };
  for (int i = 0; i < 3; ++i) {
    const PartResult p = runner.mark_next(SystemClock().now(), options);
    ASSERT_EQ(p.outcome, JobOutcome::done) << p.message;
    EXPECT_EQ(p.serials.at("serial"), 41 + i);
    ASSERT_EQ(p.objects.size(), 2u);
    EXPECT_EQ(p.objects[0].text, "SN 0000" + std::to_string(41 + i));
    EXPECT_EQ(p.objects[1].text, "LOT A17 BATCH 2026-11-23");
    EXPECT_EQ(p.text(), p.objects[0].text + "\n" + p.objects[1].text);
    for (const ObjectRun& o : p.objects) {
      ASSERT_TRUE(o.started);
      ASSERT_TRUE(o.result.quality);
      // Every part marks as well as the first: each starts where the last one left the mirrors.
      EXPECT_LT(o.result.quality->max_deviation_um, 10) << "part " << i << " " << o.name;
      EXPECT_EQ(o.result.quality->coverage, 1.0) << "part " << i << " " << o.name;
    }
    EXPECT_DOUBLE_EQ(figure(p.objects[0].result, "power_pct"), 100);
    EXPECT_DOUBLE_EQ(figure(p.objects[1].result, "power_pct"), 50);
    // 800 mm/s at 40 kHz: 20 µm; 600 mm/s at 20 kHz: 30 µm — the part reports the widest.
    EXPECT_NEAR(p.objects[0].result.pulses->spacing_max_um, 20, 0.5);
    EXPECT_NEAR(p.objects[1].result.pulses->spacing_max_um, 30, 0.75);
    EXPECT_DOUBLE_EQ(p.pulses->spacing_max_um, p.objects[1].result.pulses->spacing_max_um);
    EXPECT_NEAR(p.mark_time_s, p.objects[0].result.mark_time_s + p.objects[1].result.mark_time_s, 1e-12);
  }
  const std::vector<PartPhase> one{PartPhase::allocating, PartPhase::marking, PartPhase::recording,
                                   PartPhase::finished};
  ASSERT_EQ(phases.size(), 12u);
  EXPECT_TRUE(std::equal(one.begin(), one.end(), phases.begin()));

  const std::vector<AuditRow> rows = st.parts();
  ASSERT_EQ(rows.size(), 3u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_TRUE(rows[i].outcome);
    EXPECT_EQ(rows[i].outcome->outcome, Outcome::done);
    EXPECT_EQ(rows[i].mark.serials.at("serial"), 41 + static_cast<int>(i));
    const nlohmann::json& f = rows[i].outcome->figures;
    EXPECT_EQ(f["device"], "sim SL10");
    EXPECT_EQ(f["quality"]["class"], "high");
    EXPECT_NEAR(f["pulse_spacing_um"].get<double>(), 30, 0.75);
    EXPECT_EQ(f["objects"][1]["device_figures"]["power_pct"], 50.0);
    EXPECT_EQ(f["objects"][1]["pen"], "half");
  }
  EXPECT_EQ(test::check_store_consistent(*st.store, "serial"), (std::vector<std::int64_t>{41, 42, 43}));
}

// PartResult::times (the station's trigger-to-first-sample breakdown) against readings of the
// same steady clock the runner does not take: the phase callback's, and the drain's first block.
// Started before the allocation began, the commit before marking began, the compile inside the
// allocation, the first block after the commit.
TEST(PartRun, TimesOrderTheAllocationTheCommitAndTheFirstSample) {
  using Clock = std::chrono::steady_clock;
  PartStation st;
  SimScanner sim(st.sim_options());
  PartRunner runner = st.runner(sim);
  std::map<PartPhase, Clock::time_point> at;
  PartOptions options = virtual_time();
  options.phase = [&](PartPhase p, const auto&) { at.emplace(p, Clock::now()); };
  const auto before = Clock::now();
  const PartResult p = runner.mark_next(SystemClock().now(), options);
  ASSERT_EQ(p.outcome, JobOutcome::done) << p.message;
  const PartTimes& t = p.times;
  EXPECT_GE(t.started, before);
  EXPECT_LE(t.started, at.at(PartPhase::allocating));
  EXPECT_GE(t.committed, at.at(PartPhase::allocating));
  EXPECT_LE(t.committed, at.at(PartPhase::marking));
  EXPECT_GT(t.compile_s, 0);
  EXPECT_LT(t.compile_s, std::chrono::duration<double>(t.committed - t.started).count());
  EXPECT_GE(p.objects.at(0).result.drain.first_write, at.at(PartPhase::marking));
}

TEST(PartRun, ASecondObjectAbortedEndsThePartAndVoidsItsNumber) {
  PartStation st;
  SimScanner sim(st.sim_options());
  PartRunner runner = st.runner(sim);
  const PartResult first = runner.mark_next(SystemClock().now(), virtual_time());
  ASSERT_EQ(first.outcome, JobOutcome::done);
  const std::uint64_t s1 = first.objects[0].result.samples, s2 = first.objects[1].result.samples;
  // An abort at a sample the serial never reaches: the serial is marked, the lot line stops.
  // (The second part's serial starts where the first part's lot line ended, so its first jump
  // is longer than the first part's, by at most a field's width: 12 ms at the jump speed.)
  const std::uint64_t at = (s1 + s2) / 2;
  ASSERT_GT(at, s1 + 2000) << "the lot line must be the longer job: " << s1 << " vs " << s2;
  PartOptions options = virtual_time();
  options.job.inject = {Injection::Kind::abort, at};
  const PartResult p = runner.mark_next(SystemClock().now(), options);
  EXPECT_EQ(p.outcome, JobOutcome::aborted);
  EXPECT_EQ(p.serials.at("serial"), 42);
  ASSERT_TRUE(p.stopped_object);
  EXPECT_EQ(*p.stopped_object, 1u);
  EXPECT_EQ(p.objects[0].result.outcome, JobOutcome::done);
  EXPECT_EQ(p.objects[1].result.outcome, JobOutcome::aborted);
  EXPECT_EQ(p.objects[1].result.stopped_at, at);
  EXPECT_GT(p.objects[1].result.ink_marked, 0.0);
  EXPECT_LT(p.objects[1].result.ink_marked, 1.0);
  EXPECT_EQ(p.message.rfind("object \"lot\" (2 of 2) aborted at sample " + std::to_string(at) + ": ", 0), 0u)
      << p.message;
  EXPECT_NE(p.message.find("; marked before it: \"serial\""), std::string::npos) << p.message;
  // The store: 42 is void for good, the next part gets 43.
  const PartResult next = runner.mark_next(SystemClock().now(), virtual_time());
  EXPECT_EQ(next.outcome, JobOutcome::done);
  EXPECT_EQ(next.serials.at("serial"), 43);
  const std::vector<AuditRow> rows = st.parts();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1].outcome->outcome, Outcome::aborted);
  EXPECT_EQ(rows[1].outcome->message, p.message);
  EXPECT_EQ(rows[1].outcome->figures["stopped_at"]["object"], "lot");
  EXPECT_EQ(rows[1].outcome->figures["stopped_at"]["at"], at);
  EXPECT_EQ(rows[1].outcome->figures["objects"][0]["outcome"], "done");
  EXPECT_EQ(test::check_store_consistent(*st.store, "serial"), (std::vector<std::int64_t>{41, 42, 43}));
}

TEST(PartRun, AFailingDeviceRecordsThePartFailed) {
  PartStation st;
  SimScannerOptions o = st.sim_options();
  o.fault_at = 300;
  SimScanner sim(o);
  PartRunner runner = st.runner(sim);
  const PartResult p = runner.mark_next(SystemClock().now(), virtual_time());
  EXPECT_EQ(p.outcome, JobOutcome::failed);
  EXPECT_EQ(p.objects[0].result.outcome, JobOutcome::failed);
  ASSERT_TRUE(p.objects[0].result.fault);
  EXPECT_EQ(p.objects[0].result.fault->category, FaultCategory::device);
  EXPECT_FALSE(p.objects[1].started);
  EXPECT_NE(p.message.find("object \"serial\" (1 of 2) failed (device: simulated scanner (SL10): "
                           "injected device fault at sample 300"),
            std::string::npos)
      << p.message;
  EXPECT_NE(p.message.find("; not marked: \"lot\""), std::string::npos) << p.message;
  const std::vector<AuditRow> rows = st.parts();
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].outcome->outcome, Outcome::failed);
  EXPECT_EQ(rows[0].outcome->figures["objects"][1]["outcome"], "not_marked");
  EXPECT_EQ(rows[0].outcome->figures["objects"][0]["fault"]["at"], 300);
}

TEST(PartRun, ARefusedPartConsumesNothing) {
  std::string text = kPartRunJob;
  text.replace(text.find("\"x_mm\": -20, \"y_mm\": 3"), 22, "\"x_mm\": 45, \"y_mm\": 3");
  PartStation st(text);
  SimScanner sim(st.sim_options());
  PartRunner runner = st.runner(sim);
  try {
    runner.mark_next(SystemClock().now(), virtual_time());
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("line.json: objects[0] \"serial\": the text layout leaves the field", 0), 0u)
        << e.what();
  }
  EXPECT_TRUE(st.parts().empty());
  const CounterStatus s = st.store->status("serial", &st.job.counters.at("serial"), {}, SystemClock().now());
  EXPECT_EQ(s.next, 41);
  EXPECT_EQ(sim.samples(), 0u);  // nothing reached the device
}

TEST(PartRun, ARemarkLinksItsRowAndConsumesNoNumber) {
  PartStation st;
  SimScanner sim(st.sim_options());
  PartRunner runner = st.runner(sim);
  const PartResult first = runner.mark_next(SystemClock().now(), virtual_time());
  const PartResult again = runner.remark(first.mark_id, SystemClock().now(), virtual_time());
  EXPECT_EQ(again.outcome, JobOutcome::done);
  EXPECT_EQ(again.remark_of, first.mark_id);
  EXPECT_EQ(again.serials, first.serials);
  EXPECT_EQ(again.text(), first.text());
  EXPECT_NE(again.mark_id, first.mark_id);
  EXPECT_EQ(runner.mark_next(SystemClock().now(), virtual_time()).serials.at("serial"), 42);
  const std::vector<AuditRow> rows = st.parts();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1].mark.kind, AuditKind::remark);
  EXPECT_EQ(rows[1].mark.remark_of, first.mark_id);
  EXPECT_EQ(rows[1].outcome->outcome, Outcome::done);
  EXPECT_THROW(runner.remark(999, SystemClock().now(), virtual_time()), InputError);
}

TEST(PartRun, ABoardGetsEachObjectsPen) {
  PartStation st;
  test::RecordingCommandDevice board;
  PartRunner runner = st.runner(board);
  const PartResult p = runner.mark_next(SystemClock().now(), virtual_time());
  ASSERT_EQ(p.outcome, JobOutcome::done) << p.message;
  ASSERT_EQ(board.headers.size(), 2u);
  EXPECT_DOUBLE_EQ(board.headers[0].pens.at(0).laser.power_pct, 100);
  EXPECT_DOUBLE_EQ(board.headers[0].pens.at(0).mark_speed_mm_s, 800);
  EXPECT_DOUBLE_EQ(board.headers[1].pens.at(0).laser.power_pct, 50);
  EXPECT_DOUBLE_EQ(board.headers[1].pens.at(0).laser.frequency_khz, 20);
  EXPECT_DOUBLE_EQ(board.headers[1].pens.at(0).mark_speed_mm_s, 600);
  EXPECT_FALSE(p.quality);  // no simulator, no quality figures
}

TEST(PartRun, PensOnASampleDeviceShareItsClock) {
  std::string text = kPartRunJob;
  text.replace(text.find("\"power_pct\": 50"), 15, "\"power_pct\": 50, \"tick_us\": 5");
  PartStation st(text);
  SimScanner sim(st.sim_options());
  try {
    st.runner(sim);
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "line.json: objects[1] \"lot\": pen \"half\" ticks every 5 µs, the device sim SL10 "
              "every 10 µs: a sample-level device runs on one clock, give every pen its tick_us");
  }
}

}  // namespace
}  // namespace mark
