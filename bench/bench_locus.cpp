// Locus generation: samples per second on one core (target ≥ 100 M/s, 1000× the 100 kHz drain).
// The generator streams a whole planned job into a reused 4096-sample block, the way the job's
// producer feeds the line memory. Jobs: the 62 characters of the cps test at 5 mm (blanking pen,
// 1 m/s: lines, circular and elliptical arcs), the same text in italics (every arc an ellipse),
// one kind of element alone, and the text with planned speeds (look-ahead, power ∝ speed) with
// and without feed-forward of a first- and a second-order head model, and fed forward through a
// ZV input shaper at 10 kHz (seven taps per sample on top of the second-order terms).
#include <benchmark/benchmark.h>

#include <numbers>
#include <vector>

#include "fonts/catalog.hpp"
#include "marker/layout/layout.hpp"
#include "marker/locus/locus_generator.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/plan/plan.hpp"

namespace {

using namespace mark;

// The 62 characters at 5 mm, centred, optionally slanted.
Figure text_figure(double italic_deg) {
  LayoutOptions options;
  options.height_mm = 5;
  options.align = Align::center;
  options.italic_deg = italic_deg;
  return layout_text("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789", builtin_font(),
                     options);
}

std::vector<Command> text_job(double italic_deg) {
  const Figure f = text_figure(italic_deg);
  return plan_figure(f, default_pen(CornerStrategy::blanking, 0.12e-3, 1000, 9600)).commands;
}

// The text planned with look-ahead on SL10 (the datasheet model), optionally fed forward.
Plan planned_text_job(double italic_deg, bool feed_forward, bool second_order, double shaper_hz = 0) {
  const Figure f = text_figure(italic_deg);
  HeadModel head = head_sl10();
  head.second_order = second_order;
  PenRules r;
  r.lookahead = true;
  r.feed_forward = feed_forward;
  // 1 m/s as the constant-speed jobs above, so both have the same element mix per sample.
  Pen pen = pen_for_head(head, CornerStrategy::none, 1000, 10e-6, r);
  pen.shaper_hz = shaper_hz;
  return plan_figure(f, pen);
}

void run_plan(benchmark::State& state, const Plan& plan) {
  std::vector<ScanSample> block(4096);
  std::uint64_t samples = 0;
  for (auto _ : state) {
    LocusGenerator gen(plan);
    while (std::size_t n = gen.generate(block.data(), block.size())) {
      benchmark::DoNotOptimize(block.data());
      samples += n;
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["samples_per_job"] = static_cast<double>(LocusGenerator::count_samples(plan));
}

std::vector<Command> repeated(const Element& e, int n) {
  std::vector<Command> c;
  for (int i = 0; i < n; ++i) c.push_back(Command::mark(i % 2 ? e.reversed() : e, 1000, CommandRole::stroke));
  return c;
}

void run(benchmark::State& state, const std::vector<Command>& commands) {
  std::vector<ScanSample> block(4096);
  std::uint64_t samples = 0;
  for (auto _ : state) {
    LocusGenerator gen(commands, 10e-6);
    while (std::size_t n = gen.generate(block.data(), block.size())) {
      benchmark::DoNotOptimize(block.data());
      samples += n;
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(samples));
  state.counters["samples_per_job"] =
      static_cast<double>(LocusGenerator::count_samples(commands, 10e-6));
}

void BM_LocusText(benchmark::State& state) { run(state, text_job(0)); }
BENCHMARK(BM_LocusText)->Unit(benchmark::kMillisecond);

void BM_LocusItalicText(benchmark::State& state) { run(state, text_job(15)); }
BENCHMARK(BM_LocusItalicText)->Unit(benchmark::kMillisecond);

void BM_LocusTextPlanned(benchmark::State& state) { run_plan(state, planned_text_job(0, false, false)); }
BENCHMARK(BM_LocusTextPlanned)->Unit(benchmark::kMillisecond);

void BM_LocusTextFeedForward(benchmark::State& state) { run_plan(state, planned_text_job(0, true, false)); }
BENCHMARK(BM_LocusTextFeedForward)->Unit(benchmark::kMillisecond);

void BM_LocusTextFeedForwardSecondOrder(benchmark::State& state) {
  run_plan(state, planned_text_job(0, true, true));
}
BENCHMARK(BM_LocusTextFeedForwardSecondOrder)->Unit(benchmark::kMillisecond);

void BM_LocusTextFeedForwardShaped(benchmark::State& state) {
  run_plan(state, planned_text_job(0, true, false, 10000));
}
BENCHMARK(BM_LocusTextFeedForwardShaped)->Unit(benchmark::kMillisecond);

void BM_LocusItalicTextFeedForward(benchmark::State& state) {
  run_plan(state, planned_text_job(15, true, false));
}
BENCHMARK(BM_LocusItalicTextFeedForward)->Unit(benchmark::kMillisecond);

void BM_LocusLines(benchmark::State& state) {
  run(state, repeated(Element::line({-10, -3}, {10, 3}), 100));
}
BENCHMARK(BM_LocusLines)->Unit(benchmark::kMillisecond);

void BM_LocusArcs(benchmark::State& state) {
  run(state, repeated(Element::arc({0, 0}, 3, 0.2, 1.5 * std::numbers::pi), 100));
}
BENCHMARK(BM_LocusArcs)->Unit(benchmark::kMillisecond);

void BM_LocusEllipses(benchmark::State& state) {
  run(state, repeated(Element::ellipse({0, 0}, 4, 2, 0.3, 0.2, 1.5 * std::numbers::pi), 100));
}
BENCHMARK(BM_LocusEllipses)->Unit(benchmark::kMillisecond);

}  // namespace
