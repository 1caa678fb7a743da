// Dot-peen planning time for 200 characters (target: under 50 ms for every planner), plus the
// layout of the dot text and the gantry simulation for reference. The text is ten lines of
// twenty serial-number characters in the 5x7 dot font at 3.175 mm and, for the heaviest case,
// the same in the 10x16 font.
#include <benchmark/benchmark.h>

#include <string>

#include "marker/peen/dot_fonts.hpp"
#include "marker/peen/dot_layout.hpp"
#include "marker/peen/gantry_run.hpp"
#include "marker/peen/planners.hpp"

namespace {

std::string text_200() {
  std::string t;
  for (int line = 0; line < 10; ++line) {
    if (line) t += '\n';
    t += "SN2026-11-21-000" + std::to_string(4700 + line);  // 20 characters
  }
  return t;
}

mark::DotText dots_200(const char* font, double height_mm) {
  mark::LayoutOptions o;
  o.height_mm = height_mm;
  o.align = mark::Align::center;
  return mark::layout_dot_text(text_200(), *mark::find_dot_font(font), o);
}

void plan_200(benchmark::State& state, const char* font, double height_mm, mark::PlannerKind kind) {
  const mark::DotText text = dots_200(font, height_mm);
  const mark::PeenSetup setup{mark::tight_window(text), mark::GantryConfig{}};
  double marking_s = 0;
  for (auto _ : state) {
    mark::PeenPlan plan = mark::plan_peen(text, kind, setup);
    benchmark::DoNotOptimize(plan);
    state.PauseTiming();
    marking_s = mark::run_plan(plan, setup.gantry).total_s;
    state.ResumeTiming();
  }
  state.counters["dots"] = static_cast<double>(text.dots.size());
  state.counters["marking_s"] = marking_s;
  state.counters["s_per_char"] = marking_s / static_cast<double>(text.characters);
}

void BM_Plan200_5x7_Snake(benchmark::State& s) { plan_200(s, "5x7", 3.175, mark::PlannerKind::snake); }
void BM_Plan200_5x7_Block(benchmark::State& s) { plan_200(s, "5x7", 3.175, mark::PlannerKind::block); }
void BM_Plan200_5x7_Optimized(benchmark::State& s) { plan_200(s, "5x7", 3.175, mark::PlannerKind::optimized); }
void BM_Plan200_10x16_Optimized(benchmark::State& s) { plan_200(s, "10x16", 8.0, mark::PlannerKind::optimized); }
BENCHMARK(BM_Plan200_5x7_Snake)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK(BM_Plan200_5x7_Block)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK(BM_Plan200_5x7_Optimized)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);
BENCHMARK(BM_Plan200_10x16_Optimized)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly(true);

void BM_LayoutDots200(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(dots_200("5x7", 3.175));
}
BENCHMARK(BM_LayoutDots200)->Unit(benchmark::kMillisecond);

void BM_RunPlan200(benchmark::State& state) {
  const mark::DotText text = dots_200("5x7", 3.175);
  const mark::PeenSetup setup{mark::tight_window(text), mark::GantryConfig{}};
  const mark::PeenPlan plan = mark::plan_peen(text, mark::PlannerKind::optimized, setup);
  for (auto _ : state) benchmark::DoNotOptimize(mark::run_plan(plan, setup.gantry));
}
BENCHMARK(BM_RunPlan200)->Unit(benchmark::kMillisecond);

}  // namespace
