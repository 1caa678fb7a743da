// CNC export benchmarks:
//  * G-code lines per second for a 40-character text (layout → depression toolpath → G-code),
//    per dialect, and for the writer alone;
//  * number of motion blocks against the same text flattened into 5° chords, F-Engrave's way
//    (counters moves_ours / moves_5deg_chords; upright text keeps circular arcs, italic text
//    turns them into ellipses that we biarc-fit within 0.005 mm);
//  * pocketing time for a protrusion plate of 20 characters;
//  * the issue-25 cases: 10 / 40 / 160 rows of the 62-character sentence in QCAD's normal.cxf at
//    1 mm (layout → strokes ordered across letters → G-code), with its rapid travel and lifts,
//    and a 20-character V-carve in DejaVu Sans at 10 mm (font loaded once, outside the timing).
//    F-Engrave's figures for the same cases come from scripts/fengrave_compare.py (docs/cnc.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "fonts/catalog.hpp"
#include "marker/cnc/depression.hpp"
#include "marker/cnc/gcode_writer.hpp"
#include "marker/cnc/protrusion.hpp"
#include "marker/cnc/vcarve.hpp"
#include "marker/geometry/flatten.hpp"
#include "marker/layout/layout.hpp"

namespace {

const std::string kText40 = "MOULD 7 CAVITY 3 LOT 2026-11-21 QC PASS.";  // 40 characters
const std::string kText20 = "DIE 42 SN 2026-0815.";                      // 20 characters

mark::Figure figure(const std::string& text, double italic_deg, double height_mm = 4) {
  mark::LayoutOptions o;
  o.height_mm = height_mm;
  o.align = mark::Align::center;
  o.italic_deg = italic_deg;
  return mark::layout_text(text, mark::builtin_font(), o);
}

std::size_t count_lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

void BM_GcodeText40(benchmark::State& state) {
  const auto dialect = static_cast<mark::Dialect>(state.range(0));
  mark::CutSettings cut;
  cut.tool_diameter_mm = 0.5;
  cut.depth_mm = 0.2;
  mark::GcodeOptions o;
  o.dialect = dialect;
  std::size_t lines = 0;
  for (auto _ : state) {
    const mark::Figure f = figure(kText40, 0);
    const std::string g = mark::write_gcode(mark::depression_toolpath(f, cut), o);
    lines = count_lines(g);
    benchmark::DoNotOptimize(g.data());
  }
  state.counters["lines"] = static_cast<double>(lines);
  state.counters["lines_per_s"] = benchmark::Counter(static_cast<double>(lines), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GcodeText40)->Arg(0)->Arg(1)->Arg(2)->ArgName("linuxcnc0_fanuc1_plain2")->Unit(benchmark::kMicrosecond);

void BM_GcodeWriterOnly(benchmark::State& state) {
  mark::CutSettings cut;
  cut.depth_mm = 0.3;
  cut.depth_per_pass_mm = 0.1;
  const mark::Toolpath tp = mark::depression_toolpath(figure(kText40, 12), cut);
  mark::GcodeOptions o;
  o.dialect = mark::Dialect::plain;
  std::size_t lines = 0;
  for (auto _ : state) {
    const std::string g = mark::write_gcode(tp, o);
    lines = count_lines(g);
    benchmark::DoNotOptimize(g.data());
  }
  state.counters["lines"] = static_cast<double>(lines);
  state.counters["lines_per_s"] = benchmark::Counter(static_cast<double>(lines), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GcodeWriterOnly)->Unit(benchmark::kMicrosecond);

// Motion blocks that cut (G1 in XY, G2/G3) of one engraving pass, every occurrence counted,
// against 5° chords of every arc and ellipse of the same Figure (lines stay one block each).
void BM_MovesVsFiveDegreeChords(benchmark::State& state) {
  const double italic = static_cast<double>(state.range(0));
  const mark::Figure f = figure(kText40, italic);
  const mark::CutSettings cut;
  std::size_t ours = 0, arcs = 0;
  for (auto _ : state) {
    const mark::Toolpath tp = mark::depression_toolpath(f, cut);
    ours = arcs = 0;
    for (const mark::ToolMove& m : mark::expand_moves(tp)) {
      if (m.kind == mark::MoveKind::arc) ++arcs;
      if (m.kind == mark::MoveKind::arc || (m.kind == mark::MoveKind::feed && m.end.z() < 0)) ++ours;
    }
    benchmark::DoNotOptimize(tp.subs.data());
  }
  // Plunges are feed moves at depth too: one per stroke; take them out.
  std::size_t plunges = 0;
  const mark::Toolpath tp = mark::depression_toolpath(f, cut);
  const std::vector<mark::ToolMove> moves = mark::expand_moves(tp);
  for (std::size_t k = 1; k < moves.size(); ++k)
    plunges += moves[k].kind == mark::MoveKind::feed && moves[k].end.head<2>() == moves[k - 1].end.head<2>();
  ours -= plunges;
  std::size_t chords = 0;
  for (const mark::PlacedGlyph& g : f.glyphs)
    for (const mark::Element& e : g.elements)
      if (e.laser()) chords += mark::chord_element(e, 5 * std::numbers::pi / 180).size() - 1;
  state.counters["moves_ours"] = static_cast<double>(ours);
  state.counters["arcs_ours"] = static_cast<double>(arcs);
  state.counters["moves_5deg_chords"] = static_cast<double>(chords);
  state.counters["chords_per_move"] = static_cast<double>(chords) / static_cast<double>(ours);
}
BENCHMARK(BM_MovesVsFiveDegreeChords)->Arg(0)->Arg(12)->ArgName("italic_deg")->Unit(benchmark::kMicrosecond);

void BM_ProtrusionPlate20(benchmark::State& state) {
  const mark::Figure f = figure(kText20, 0, 5);
  mark::CutSettings cut;
  cut.tool_diameter_mm = 0.6;
  cut.depth_mm = 0.5;
  cut.depth_per_pass_mm = 0.25;
  std::size_t loops = 0, moves = 0;
  for (auto _ : state) {
    const mark::ProtrusionResult r = mark::protrusion_toolpath(f, cut, {});
    loops = r.loops;
    moves = r.toolpath.steps.size();
    benchmark::DoNotOptimize(r.toolpath.steps.data());
  }
  state.counters["loops_per_pass"] = static_cast<double>(loops);
  state.counters["moves"] = static_cast<double>(moves);
}
BENCHMARK(BM_ProtrusionPlate20)->Unit(benchmark::kMillisecond);

const std::string kSentence = "The quick brown fox jumps over the lazy dog. 0123456789 ABCDEF";  // 62 characters

// Rows of the sentence at 1 mm in normal.cxf, the whole command's work but the font's loading:
// layout, strokes, the visiting order, toolpath, G-code. The growth from 10 to 160 rows is the
// figure the issue asks for (at most 16 times + start-up).
void BM_GcodeRows(benchmark::State& state) {
  static const auto font = mark::open_font(std::string(MARKER_SOURCE_DIR) + "/tests/fonts/data/normal.cxf", nullptr);
  std::string text;
  for (int k = 0; k < state.range(0); ++k) text += (k ? "\n" : "") + kSentence;
  mark::LayoutOptions o;
  o.height_mm = 1;
  mark::CutSettings cut;
  cut.tool_diameter_mm = 0.1;
  cut.depth_mm = 0.1;
  std::size_t lines = 0;
  mark::RapidTravel travel;
  for (auto _ : state) {
    const mark::Figure f = mark::layout_text(text, *font, o);
    const mark::Toolpath tp = mark::depression_toolpath(f, cut);
    const std::string g = mark::write_gcode(tp, mark::GcodeOptions{});
    lines = count_lines(g);
    benchmark::DoNotOptimize(g.data());
    state.PauseTiming();
    travel = mark::rapid_travel(tp);
    state.ResumeTiming();
  }
  state.counters["lines"] = static_cast<double>(lines);
  state.counters["rapid_mm"] = travel.xy_mm;
  state.counters["retracts"] = static_cast<double>(travel.retracts);
}
BENCHMARK(BM_GcodeRows)->Arg(10)->Arg(40)->Arg(160)->ArgName("rows")->Unit(benchmark::kMillisecond);

// 20 characters of DejaVu Sans at 10 mm, v-carved with a 60° bit (no depth cap): medial axes,
// paths, G-code.
void BM_VCarve20(benchmark::State& state) {
  static const auto font = mark::open_font("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", nullptr);
  mark::LayoutOptions o;
  o.height_mm = 10;
  mark::CutSettings cut;
  cut.tool_diameter_mm = 20;
  const mark::VCarveSettings v;
  std::size_t lines = 0, edges = 0;
  for (auto _ : state) {
    const mark::Figure f = mark::layout_text("Serial No. 2026-0815", *font, o);
    const mark::VCarveResult r = mark::vcarve_toolpath(f, cut, v);
    const std::string g = mark::write_gcode(r.toolpath, mark::GcodeOptions{});
    lines = count_lines(g);
    edges = r.axis_edges;
    benchmark::DoNotOptimize(g.data());
  }
  state.counters["lines"] = static_cast<double>(lines);
  state.counters["axis_edges"] = static_cast<double>(edges);
}
BENCHMARK(BM_VCarve20)->Unit(benchmark::kMillisecond);

}  // namespace
