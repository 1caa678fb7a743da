// Compile latency (target < 50 µs): a 20-character serial number from text to its first sample
// in the line memory — layout, plan (blanking on SL10), the refusal checks, the locus
// generator's first block, the push into the line memory. The block is popped again inside the
// loop (a 3 kB copy) so the memory never fills.
#include <benchmark/benchmark.h>

#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/locus/locus_generator.hpp"
#include "ringbuffer/line_memory.hpp"

namespace {

using namespace mark;

JobSpec serial_spec(CornerStrategy corner, double italic_deg, bool feed_forward = false) {
  JobSpec spec;
  spec.text = "SN2026-11-21-0004711";  // 20 characters
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 3;
  spec.layout.align = Align::center;
  spec.layout.italic_deg = italic_deg;
  spec.head = head_sl10();
  PenRules rules;
  rules.feed_forward = feed_forward;
  spec.pen = pen_for_head(spec.head, corner, feed_forward ? 3000 : 1000, 10e-6, rules);
  return spec;
}

void compile_to_first_sample(benchmark::State& state, const JobSpec& spec) {
  LineMemory<ScanSample> memory(1u << 16);
  std::vector<ScanSample> block(256);
  for (auto _ : state) {
    const CompiledJob job = compile_job(spec);
    LocusGenerator locus(job.plan);
    const std::size_t n = locus.generate(block.data(), block.size());
    memory.push(std::span<const ScanSample>(block.data(), n));
    benchmark::DoNotOptimize(memory.pop(std::span<ScanSample>(block)));
  }
}

void BM_CompileSerial20Blanking(benchmark::State& state) {
  compile_to_first_sample(state, serial_spec(CornerStrategy::blanking, 0));
}
BENCHMARK(BM_CompileSerial20Blanking)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_CompileSerial20Delays(benchmark::State& state) {
  compile_to_first_sample(state, serial_spec(CornerStrategy::delays, 0));
}
BENCHMARK(BM_CompileSerial20Delays)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_CompileSerial20BlankingItalic(benchmark::State& state) {
  compile_to_first_sample(state, serial_spec(CornerStrategy::blanking, 12));
}
BENCHMARK(BM_CompileSerial20BlankingItalic)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

// Look-ahead planning and feed-forward: the speed passes over the whole job and the planned
// locus's first block.
void BM_CompileSerial20FeedForward(benchmark::State& state) {
  compile_to_first_sample(state, serial_spec(CornerStrategy::none, 0, true));
}
BENCHMARK(BM_CompileSerial20FeedForward)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
