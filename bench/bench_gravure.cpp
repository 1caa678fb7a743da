// Gravure: image to filtered stylus samples, samples per second on one core (target ≥ 20 M/s,
// 100× the 200 kHz stylus clock). A 40 × 40 mm photograph-like image (smooth tone with a
// line-work band, 4 px a cell at 70 lines/cm: 78 400 cells, 2.5 M samples) runs through the whole
// producer — cells, control points, the monotone cubic through them, sampling at 200 kHz, the
// notch / emphasis biquads — into a reused 4096-sample block, the way the job feeds the line
// memory. Parts are timed alone too: the toolpath without filters, and the filters alone.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "marker/gravure/biquad_cascade.hpp"
#include "marker/gravure/head_design.hpp"
#include "marker/gravure/image_cells.hpp"
#include "marker/gravure/stylus_run.hpp"
#include "marker/gravure/stylus_toolpath.hpp"

namespace {

using namespace mark;

GrayImage artwork() {
  const int w = 1120, h = 1120;  // 40 mm at 28 px/mm
  GrayImage img{w, h, std::vector<float>(static_cast<std::size_t>(w) * h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float v = 0.5f + 0.45f * std::sin(x * 0.013f) * std::cos(y * 0.017f + x * 0.004f);
      if (y > 800 && y < 900) v = (x % 7 < 2 || (y / 4) % 3 == 0) ? 0.0f : 1.0f;  // type-like band
      img.pixels[static_cast<std::size_t>(y) * w + x] = v;
    }
  return img;
}

void BM_ImageToFilteredSamples(benchmark::State& state) {
  const GrayImage img = artwork();
  const FilterBank bank = design_for_head(default_stylus_head());
  std::vector<StylusSample> block(4096);
  std::uint64_t samples = 0;
  for (auto _ : state) {
    ImageCells cells(img, nullptr, GravureScreen{}, 28);
    StylusToolpath toolpath(cells, {GravureSetup{}, 6250, 1.8});
    StylusSampleStream stream(toolpath, &bank);
    while (const std::size_t n = stream.next(block)) samples += n;
    benchmark::DoNotOptimize(block.data());
  }
  state.counters["samples_per_s"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kIsRate);
  state.counters["x_real_time"] =
      benchmark::Counter(static_cast<double>(samples) / 200000, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ImageToFilteredSamples)->Unit(benchmark::kMillisecond);

void BM_ToolpathOnly(benchmark::State& state) {
  const GrayImage img = artwork();
  std::vector<double> block(4096);
  std::uint64_t samples = 0;
  for (auto _ : state) {
    ImageCells cells(img, nullptr, GravureScreen{}, 28);
    StylusToolpath toolpath(cells, {GravureSetup{}, 6250, 0});
    while (const std::size_t n = toolpath.next(block)) samples += n;
    benchmark::DoNotOptimize(block.data());
  }
  state.counters["samples_per_s"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ToolpathOnly)->Unit(benchmark::kMillisecond);

void BM_FiltersOnly(benchmark::State& state) {
  BiquadCascade cascade(design_for_head(default_stylus_head()));
  std::vector<double> input(4096), block(4096);
  for (std::size_t i = 0; i < input.size(); ++i) input[i] = 20 * std::sin(0.2 * static_cast<double>(i));
  std::uint64_t samples = 0;
  for (auto _ : state) {
    block = input;  // fresh input each time (filtering its own output would grow without bound)
    cascade.process(block);
    samples += block.size();
    benchmark::DoNotOptimize(block.data());
  }
  state.counters["samples_per_s"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FiltersOnly);

}  // namespace
