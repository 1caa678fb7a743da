// Cost of the simulated scanner and of the quality figures on a job shaped like the
// characters-per-second test (62 cells of 1 mm text, ~4 mm of strokes each: a zigzag and a
// circle), so the speed search's budget per evaluation is known.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "driver/sim/quality.hpp"
#include "driver/sim/sim_scanner.hpp"

namespace mark {
namespace {

struct Job {
  std::vector<ScanSample> samples;
  std::vector<std::vector<Vec2>> intended;
};

// Samples at constant speed along a polyline (laser as given), the last on its end.
void trace(std::vector<ScanSample>& out, Vec2& at, const std::vector<Vec2>& pts, double step,
           bool laser) {
  for (const Vec2& p : pts) {
    const int n = std::max(1, static_cast<int>(std::ceil(norm(p - at) / step)));
    for (int i = 1; i <= n; ++i) {
      const Vec2 q = at + (static_cast<double>(i) / n) * (p - at);
      out.push_back({static_cast<float>(q.x), static_cast<float>(q.y), laser, 255});
    }
    at = p;
  }
}

std::vector<Vec2> densify(const std::vector<Vec2>& pts, double step) {
  std::vector<Vec2> d{pts.front()};
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const int n = std::max(1, static_cast<int>(std::ceil(norm(pts[i] - pts[i - 1]) / step)));
    for (int k = 1; k <= n; ++k) d.push_back(pts[i - 1] + (static_cast<double>(k) / n) * (pts[i] - pts[i - 1]));
  }
  return d;
}

Job make_job(double speed_mm_s) {
  Job job;
  const double tick = 10e-6;
  Vec2 at{0, 0};
  for (int c = 0; c < 62; ++c) {
    const double x0 = -25 + 0.8 * c;
    const std::vector<Vec2> zig{{x0, 0}, {x0 + 0.2, 1}, {x0 + 0.35, 0}, {x0 + 0.5, 1}, {x0 + 0.6, 0}};
    std::vector<Vec2> circle;
    for (int k = 0; k <= 64; ++k)
      circle.push_back({x0 + 0.3 + 0.2 * std::cos(k * M_PI / 32), 0.5 + 0.2 * std::sin(k * M_PI / 32)});
    for (const std::vector<Vec2>* stroke : {&zig, static_cast<const std::vector<Vec2>*>(&circle)}) {
      trace(job.samples, at, {stroke->front()}, 5000 * tick, false);       // jump at 5 m/s
      for (int i = 0; i < 20; ++i) job.samples.push_back(job.samples.back());  // jump delay
      trace(job.samples, at, *stroke, speed_mm_s * tick, true);
      job.samples.back().laser = false;
      job.intended.push_back(densify(*stroke, 0.005));
    }
  }
  return job;
}

void BM_SimScanner(benchmark::State& state) {
  const Job job = make_job(static_cast<double>(state.range(0)));
  for (auto _ : state) {
    SimScanner sim;
    sim.write(job.samples);
    benchmark::DoNotOptimize(sim.dose().total());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * job.samples.size()));
  state.counters["samples"] = static_cast<double>(job.samples.size());
}
BENCHMARK(BM_SimScanner)->ArgName("speed_mm_s")->Arg(1000)->Arg(3000)->Unit(benchmark::kMillisecond);

// The same samples as a job begun with a pen (Q-switched at 30 kHz), with and without the pulse
// raster for the picture (SimScanner::picture_dose): what laying every pulse costs the drain
// (write() alone: the reserve before the first sample is not timed).
void BM_SimScannerPulsePicture(benchmark::State& state) {
  const Job job = make_job(static_cast<double>(state.range(0)));
  JobHeader header;
  header.pens.push_back(DevicePen{});
  header.lit_paths = job.intended;
  SimScannerOptions o;
  o.pulse_picture = state.range(1) != 0;
  SimScanner sim(o);
  for (auto _ : state) {
    state.PauseTiming();  // begin_job's reserve runs before a job's first sample, off its clock
    sim.reset();
    sim.begin_job(header);
    state.ResumeTiming();
    sim.write(job.samples);
    sim.end_job();
    benchmark::DoNotOptimize(sim.picture_dose().total());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * job.samples.size()));
}
BENCHMARK(BM_SimScannerPulsePicture)
    ->ArgNames({"speed_mm_s", "pulse_picture"})
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->Args({3000, 0})
    ->Args({3000, 1})
    ->Unit(benchmark::kMillisecond);

void BM_Quality(benchmark::State& state) {
  const Job job = make_job(static_cast<double>(state.range(0)));
  SimScanner sim;
  sim.write(job.samples);
  const QualityReference reference(job.intended);  // once per set of strokes, as a speed search would
  Quality q;
  for (auto _ : state) {
    q = reference.evaluate(sim.lit_paths(), sim.dose(), sim.intent());
    benchmark::ClobberMemory();  // (DoNotOptimize on a double member garbles it with GCC)
  }
  char label[160];
  std::snprintf(label, sizeof label, "lit %zu, max dev %.1f um, coverage %.3f, dose ratio %.2f",
                q.lit_points, q.max_deviation_um, q.coverage, q.dose_ratio_max);
  state.SetLabel(label);
}
BENCHMARK(BM_Quality)->ArgName("speed_mm_s")->Arg(1000)->Arg(3000)->Unit(benchmark::kMillisecond);

void BM_QualityReference(benchmark::State& state) {
  const Job job = make_job(1000);
  for (auto _ : state) {
    QualityReference reference(job.intended);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_QualityReference)->Unit(benchmark::kMillisecond);

// Sizing the dose raster before a job's first sample (SimScanner::begin_job): every tile within
// the dose margin of the job's lit paths, margin 1 mm (SL10 at 2000 mm/s). On the trigger path
// of a station on the simulated scanner: the time from the serial's commit to the first sample.
void BM_DoseReserve(benchmark::State& state) {
  const Job job = make_job(1000);
  DoseRaster dose(0.005);
  for (auto _ : state) {
    dose.clear();
    dose.reserve_along(job.intended, 1.0);
    benchmark::DoNotOptimize(dose.tiles());
  }
  state.counters["tiles"] = static_cast<double>(dose.tiles());
}
BENCHMARK(BM_DoseReserve)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mark
