// The next part of a series (target < 20 µs median): a 20-character template whose serial
// changes its last 2 digits — render the template, lay out only the changed characters again
// (relayout_text: shapes computed once, unchanged glyphs kept), plan only from the first changed
// glyph (Replanner), and check the field. Against it: the same text rendered, laid out and
// planned from scratch.
#include <benchmark/benchmark.h>

#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/layout/layout.hpp"
#include "marker/plan/replan.hpp"
#include "marker/vars/render.hpp"

namespace {

using namespace mark;

struct Series {
  std::shared_ptr<const StrokeFont> font = open_font(kBuiltinFontName);
  TextTemplate text = TextTemplate::parse("SN 2026-A17-{serial:8}", "bench");  // 20 characters
  std::map<std::string, CounterSpec> counters;
  std::map<std::string, std::int64_t> serials{{"serial", 4711}};
  MarkValues values;
  LayoutOptions layout;
  Pen pen = pen_for_head(head_sl10(), CornerStrategy::blanking, 1000);
  Field field{110};
  std::string rendered;

  Series() {
    CounterSpec s;
    s.name = "serial";
    counters["serial"] = s;
    values.counters = &counters;
    values.serials = &serials;
    layout.height_mm = 3;
    layout.base = Point(-20, 0);
  }
  // +11: the last two digits change (…4711 → …4722 → …4733 …).
  const std::string& next() {
    serials["serial"] = 4711 + (serials["serial"] - 4711 + 11) % 88;
    rendered.clear();
    render(text, values, rendered);
    return rendered;
  }
};

void BM_NextPartIncremental(benchmark::State& state) {
  Series s;
  Figure figure;
  Replanner replanner(s.pen);
  relayout_text(s.next(), *s.font, s.layout, figure);
  replanner.update(figure);
  for (auto _ : state) {
    relayout_text(s.next(), *s.font, s.layout, figure);
    const Plan& plan = replanner.update(figure);
    require_inside(replanner.bounds(), s.field, "the job");
    benchmark::DoNotOptimize(plan.commands.data());
  }
  state.counters["replanned_glyphs"] = static_cast<double>(replanner.replanned_glyphs());
}
BENCHMARK(BM_NextPartIncremental)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_NextPartFromScratch(benchmark::State& state) {
  Series s;
  for (auto _ : state) {
    const Figure figure = layout_text(s.next(), *s.font, s.layout);
    const Plan plan = plan_figure(figure, s.pen);
    require_inside(plan.bounds(), s.field, "the job");
    benchmark::DoNotOptimize(plan.commands.data());
  }
}
BENCHMARK(BM_NextPartFromScratch)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
