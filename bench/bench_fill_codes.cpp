// Encode + hatch + plan for a 16 × 16 Data Matrix, and layout + fill + plan for 20 characters of
// filled DejaVu Sans at 3 mm: time per run, hatch lines, and the plan's jump length with the
// ordered serpentine hatch against a naive one (scanline order, every line the same way).
// Verification of an 8 mm code (part image, camera, libdmtx) is timed on its own.
#include <benchmark/benchmark.h>

#include "driver/sim_scanner.hpp"
#include "fonts/catalog.hpp"
#include "marker/codes/code_job.hpp"
#include "marker/fill/fill.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/layout/layout.hpp"
#include "marker/plan/plan.hpp"

namespace {

using namespace mark;

const Pen& pen() {
  static const Pen p = pen_for_head(head_sl10(), CornerStrategy::blanking, 1000);
  return p;
}

CodeSpec dm16() {
  CodeSpec s;
  s.data = "SN 2026-000123";
  s.matrix_rows = s.matrix_cols = 16;
  return s;
}

CodeLayout dm_layout(HatchOrder order) {
  CodeLayout l;
  l.module_mm = 0.3;
  l.fill.order = order;
  if (order == HatchOrder::raster) l.fill.direction = HatchDirection::unidirectional;
  return l;
}

void BM_DataMatrix16_EncodeHatchPlan(benchmark::State& state) {
  const CodeSpec spec = dm16();
  const CodeLayout layout = dm_layout(HatchOrder::short_jumps);
  Plan plan;
  std::size_t lines = 0;
  for (auto _ : state) {
    const PlacedCode code = place_encoded(spec, layout);
    plan = plan_figure(code_figure(code), pen());
    lines = code.stats.hatch_lines;
    benchmark::DoNotOptimize(plan);
  }
  const Plan naive = plan_figure(code_figure(place_encoded(spec, dm_layout(HatchOrder::raster))), pen());
  state.counters["hatch_lines"] = static_cast<double>(lines);
  state.counters["jump_mm"] = plan.jump_length_mm;
  state.counters["naive_jump_mm"] = naive.jump_length_mm;
  state.counters["mark_time_s"] = plan.duration_s();
  state.counters["naive_mark_time_s"] = naive.duration_s();
}
BENCHMARK(BM_DataMatrix16_EncodeHatchPlan)->Unit(benchmark::kMicrosecond)->Repetitions(3)->ReportAggregatesOnly(true);

const StrokeFont& dejavu() {
  static const std::shared_ptr<const StrokeFont> f = open_font("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
  return *f;
}

void BM_FilledDejaVu20_LayoutFillPlan(benchmark::State& state) {
  const std::string text = "SN2026-11-21-0004711";  // 20 characters
  LayoutOptions lo;
  lo.height_mm = 3;
  lo.align = Align::center;
  FillOptions fill;
  Plan plan;
  FillStats stats;
  dejavu();  // loading the font (about a second) is not part of the run
  for (auto _ : state) {
    const Figure filled = fill_figure(layout_text(text, dejavu(), lo), fill, &stats);
    plan = plan_figure(filled, pen());
    benchmark::DoNotOptimize(plan);
  }
  fill.order = HatchOrder::raster;
  fill.direction = HatchDirection::unidirectional;
  FillStats naive_stats;
  const Plan naive = plan_figure(fill_figure(layout_text(text, dejavu(), lo), fill, &naive_stats), pen());
  state.counters["hatch_lines"] = static_cast<double>(stats.hatch_lines);
  state.counters["jump_mm"] = plan.jump_length_mm;
  state.counters["naive_jump_mm"] = naive.jump_length_mm;
  state.counters["mark_time_s"] = plan.duration_s();
  state.counters["naive_mark_time_s"] = naive.duration_s();
}
BENCHMARK(BM_FilledDejaVu20_LayoutFillPlan)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);

void BM_Verify8mmDataMatrix(benchmark::State& state) {
  CodeJob job;
  job.spec = dm16();
  job.layout.module_mm = 0.5;
  job.pen = pen();
  const CodeJobResult marked = run_code_job(job);
  for (auto _ : state) {
    const CodeVerification v = verify_code(marked.code, job.spec, marked.scanner->dose(), job.verify);
    if (!v.data_match) state.SkipWithError("the 8 mm code did not read");
    benchmark::DoNotOptimize(v);
  }
}
BENCHMARK(BM_Verify8mmDataMatrix)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);

}  // namespace
