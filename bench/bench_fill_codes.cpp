// Encode + hatch + plan for a 16 × 16 Data Matrix, and layout + fill + plan for 20 characters of
// filled DejaVu Sans at 3 mm: time per run, hatch lines, and the plan's jump length with the
// ordered serpentine hatch against a naive one (scanline order, every line the same way).
// Verification of an 8 mm code (part image, camera, libdmtx) is timed on its own.
#include <benchmark/benchmark.h>

#include "driver/sim/sim_scanner.hpp"
#include "fonts/catalog.hpp"
#include "marker/codes/code_object.hpp"
#include "marker/fill/fill.hpp"
#include "marker/job/code_photo.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/simulate_plan.hpp"
#include "marker/layout/layout.hpp"
#include "marker/plan/plan.hpp"

namespace {

using namespace mark;

const Pen& pen() {
  static const Pen p = pen_for_head(head_sl10(), CornerStrategy::blanking, 1000);
  return p;
}

CodeObject dm16(double module_mm, HatchOrder order = HatchOrder::short_jumps) {
  CodeObject c;
  c.spec.data = "SN 2026-000123";
  c.spec.matrix_rows = c.spec.matrix_cols = 16;
  c.layout.module_mm = module_mm;
  c.layout.fill.order = order;
  if (order == HatchOrder::raster) c.layout.fill.direction = HatchDirection::unidirectional;
  return c;
}

void BM_DataMatrix16_EncodeHatchPlan(benchmark::State& state) {
  const CodeObject object = dm16(0.3);
  Plan plan;
  std::size_t lines = 0;
  for (auto _ : state) {
    const PlacedCode code = place_encoded(object);
    plan = plan_figure(code_figure(code), pen());
    lines = code.stats.hatch_lines;
    benchmark::DoNotOptimize(plan);
  }
  const Plan naive = plan_figure(code_figure(place_encoded(dm16(0.3, HatchOrder::raster))), pen());
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
  JobSpec job;
  job.codes.push_back(dm16(0.5));
  job.pen = pen();
  const SimulatedJob marked = simulate_job(job);
  for (auto _ : state) {
    const CodeVerification v =
        check_code(marked.job.codes.front(), job.codes.front().spec, marked.scanner->picture_dose(), job.verify);
    if (!v.data_match) state.SkipWithError("the 8 mm code did not read");
    benchmark::DoNotOptimize(v);
  }
}
BENCHMARK(BM_Verify8mmDataMatrix)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);

}  // namespace
