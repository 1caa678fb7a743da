// Layout of a 20-character serial number into a Figure (target: under 5 µs median).
#include <benchmark/benchmark.h>

#include "fonts/catalog.hpp"
#include "marker/layout/layout.hpp"

namespace {

void BM_LayoutSerial20(benchmark::State& state) {
  const mark::StrokeFont& font = mark::builtin_font();
  mark::LayoutOptions options;
  options.height_mm = 3;
  options.align = mark::Align::center;
  const std::string serial = "SN2026-11-21-0004711";  // 20 characters
  for (auto _ : state) {
    mark::Figure f = mark::layout_text(serial, font, options);
    benchmark::DoNotOptimize(f);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(serial.size()));
}
BENCHMARK(BM_LayoutSerial20)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_LayoutSerial20Circular(benchmark::State& state) {
  const mark::StrokeFont& font = mark::builtin_font();
  mark::LayoutOptions options;
  options.height_mm = 3;
  options.italic_deg = 12;
  options.circle = mark::CircleFit{{0, 0}, 30, std::nullopt, false};
  const std::string serial = "SN2026-11-21-0004711";
  for (auto _ : state) {
    mark::Figure f = mark::layout_text(serial, font, options);
    benchmark::DoNotOptimize(f);
  }
}
BENCHMARK(BM_LayoutSerial20Circular)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
