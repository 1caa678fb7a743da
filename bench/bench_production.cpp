// Production marking throughput: parts per second in virtual time (the simulated scanner takes
// samples as fast as they come) for a 20-character serial job, and what dominates. One part =
// allocate its serial (one SQLite transaction with synchronous=FULL, on the local disk) →
// render, lay out and plan incrementally → mark on the simulated SL10 → quality figures →
// record the outcome (a second transaction). Against it the pieces alone:
//   BM_StoreOnly        allocation + outcome, no marking
//   BM_StoreOnlyPostgres  the same on a private PostgreSQL server (a Unix socket, every commit
//                         flushed to disk: fsync and synchronous_commit on, as a plant's server)
//   BM_MarkOnly         compile + mark + quality, no store
//   BM_MarkNoQuality    compile + mark, neither store nor quality figures
//   BM_Part             everything (PartRunner::mark_next)
// Counters: parts_per_s (wall clock: the store waits for the disk), device_s_per_part (the
// mark's own time on a real head). The CPU column is the process's own work.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "marker/job/sim_evaluator.hpp"
#include "marker/production/part_run.hpp"
#include "marker/store/digest.hpp"
#include "marker/store/open_store.hpp"
#include "tests/marker/store/postgres_server.hpp"

namespace {

using namespace mark;

constexpr const char* kJob = R"({
  "format": "marker-job/1",
  "time_zone": "UTC",
  "counters": {"serial": {"start": 4711, "width": 8}},
  "pens": {"p": {"speed_mm_s": 900, "power_pct": 80, "frequency_khz": 40}},
  "objects": [{"name": "serial", "template": "SN 2026-A17-{serial}", "height_mm": 3, "x_mm": -20}]
})";

struct Line {
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("marker-bench-production-" + std::to_string(::getpid()));
  JobFile job = parse_job(kJob, "bench.json");
  JobFonts fonts{job};
  std::unique_ptr<SerialStore> store;
  MarkContext context;
  SimScanner scanner{simulator_options(object_spec(job, job.objects.front(), "", fonts))};

  // `store_url`: a PostgreSQL URL; empty: a SQLite file in `dir`.
  explicit Line(const std::string& store_url = {}) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    store = open_store(store_url.empty() ? (dir / "bench.serials.sqlite").string() : store_url, StoreAccess::create);
    context.station = "bench";
    context.job = "bench.json";
    context.job_sha256 = sha256_hex(kJob);
    context.now = SystemClock().now();
    store->start_station(context);
    store->create_missing(job.used_counters(), job.shifts, context);
  }
  ~Line() {
    store.reset();
    std::filesystem::remove_all(dir);
  }
};

void rate(benchmark::State& state, double device_s) {
  state.counters["parts_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  if (device_s > 0)
    state.counters["device_s_per_part"] = device_s / static_cast<double>(state.iterations());
}

void store_parts(benchmark::State& state, Line& line) {
  const auto counters = line.job.used_counters();
  for (auto _ : state) {
    line.context.now = SystemClock().now();
    const Allocation a = line.store->allocate(counters, line.job.shifts, line.context, [&](const auto& serials) {
      return render_objects(line.job, {}, line.context.now, serials);
    });
    OutcomeRecord o;
    o.time_utc = a.time_utc;
    o.figures = {{"samples", 16000}, {"mark_time_s", 0.16}};
    line.store->record_outcome(a.mark_id, o);
  }
  rate(state, 0);
}

void BM_StoreOnly(benchmark::State& state) {
  Line line;
  store_parts(state, line);
}

void BM_StoreOnlyPostgres(benchmark::State& state) {
  const auto bin = test::PostgresServer::find_binaries();
  if (bin.empty()) {
    state.SkipWithError("no PostgreSQL server binaries (Debian postgresql) under /usr/lib/postgresql");
    return;
  }
  test::PostgresServer server(bin, true);
  Line line(server.url());
  store_parts(state, line);
}
BENCHMARK(BM_StoreOnly)->Unit(benchmark::kMillisecond)->MinTime(2)->UseRealTime();
BENCHMARK(BM_StoreOnlyPostgres)->Unit(benchmark::kMillisecond)->MinTime(2)->UseRealTime();

void mark_only(benchmark::State& state, bool quality) {
  Line line;
  JobCompiler compiler(object_spec(line.job, line.job.objects.front(), "", line.fonts), DeviceLevel::samples);
  JobOptions options;
  options.virtual_time = true;
  std::map<std::string, std::int64_t> serials{{"serial", 4711}};
  double device_s = 0;
  for (auto _ : state) {
    const std::string text = render_objects(line.job, {}, SystemClock().now(), serials).front().text;
    ++serials["serial"];
    JobSpec spec = compiler.spec();
    spec.text = text;
    JobResult r = run_compiled_job(spec, compiler.compile(text), options, line.scanner);
    if (quality) r.quality = simulated_quality(r, line.scanner, mark_intent(spec, line.scanner));
    device_s += r.mark_time_s;
    benchmark::DoNotOptimize(r);
  }
  rate(state, device_s);
}
void BM_MarkOnly(benchmark::State& state) { mark_only(state, true); }
void BM_MarkNoQuality(benchmark::State& state) { mark_only(state, false); }
BENCHMARK(BM_MarkOnly)->Unit(benchmark::kMillisecond)->MinTime(2)->UseRealTime();
BENCHMARK(BM_MarkNoQuality)->Unit(benchmark::kMillisecond)->MinTime(2)->UseRealTime();

void BM_Part(benchmark::State& state) {
  Line line;
  PartRunner runner(line.job, line.fonts, {}, line.scanner, *line.store, line.context);
  SimEvaluator evaluator(line.scanner);  // quality figures included, as the command line marks
  PartOptions options;
  options.job.virtual_time = true;
  options.job.evaluator = &evaluator;
  double device_s = 0;
  for (auto _ : state) {
    const PartResult p = runner.mark_next(SystemClock().now(), options);
    if (p.outcome != JobOutcome::done) state.SkipWithError(p.message.c_str());
    device_s += p.mark_time_s;
  }
  rate(state, device_s);
}
BENCHMARK(BM_Part)->Unit(benchmark::kMillisecond)->MinTime(2)->UseRealTime();

}  // namespace
