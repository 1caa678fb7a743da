// Font loading speed: a Debian Hershey font (target < 2 ms) and LibreCAD's unicode.lff, 2622
// glyphs with 1186 bulge arcs (target < 20 ms). "Parse" runs on text already in memory, "Load"
// includes reading the file. Outline fonts make glyphs on first use (docs/fonts.md): opening
// DejaVu Sans and making the glyphs of "SN 42" (target < 10 ms; it was 1.4 s when every glyph was
// fitted on opening).
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "fonts/loaders.hpp"

namespace {

const std::string kRowmans = "/usr/share/hershey-fonts/rowmans.jhf";
const std::string kGothicger = "/usr/share/hershey-fonts/gothicger.jhf";
const std::string kUnicode = "/usr/share/librecad/fonts/unicode.lff";
const std::string kStandard = "/usr/share/librecad/fonts/standard.lff";

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

template <class Parse>
void parse_file(benchmark::State& state, const std::string& path, Parse parse) {
  const std::string text = read_text(path);
  std::size_t glyphs = 0;
  for (auto _ : state) {
    mark::Warnings warnings;
    const mark::StrokeFont font = parse(text, path, &warnings);
    glyphs = font.size();
    benchmark::DoNotOptimize(glyphs);
  }
  state.counters["glyphs"] = static_cast<double>(glyphs);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}

void load_file(benchmark::State& state, const std::string& path) {
  for (auto _ : state) {
    mark::Warnings warnings;
    const mark::StrokeFont font = mark::load_font_file(path, &warnings);
    benchmark::DoNotOptimize(font.size());
  }
}

void BM_ParseHersheyRowmans(benchmark::State& s) { parse_file(s, kRowmans, mark::parse_jhf); }
void BM_ParseHersheyGothicger(benchmark::State& s) { parse_file(s, kGothicger, mark::parse_jhf); }
void BM_LoadHersheyRowmans(benchmark::State& s) { load_file(s, kRowmans); }
void BM_ParseLffStandard(benchmark::State& s) { parse_file(s, kStandard, mark::parse_lff); }
void BM_ParseLffUnicode(benchmark::State& s) { parse_file(s, kUnicode, mark::parse_lff); }
void BM_LoadLffUnicode(benchmark::State& s) { load_file(s, kUnicode); }

// Opens the font and makes the glyphs of `text`.
void open_and_make(benchmark::State& state, const std::string& path, const std::u32string& text) {
  std::size_t elements = 0;
  for (auto _ : state) {
    const mark::StrokeFont font = mark::load_outline_font(path);
    elements = 0;
    for (char32_t c : text) elements += font.glyph(c).elements.size();
    benchmark::DoNotOptimize(elements);
  }
  state.counters["elements"] = static_cast<double>(elements);
}

void BM_OpenDejaVuMakeSN42(benchmark::State& s) {
  open_and_make(s, "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", U"SN 42");
}

BENCHMARK(BM_OpenDejaVuMakeSN42)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseHersheyRowmans)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParseHersheyGothicger)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LoadHersheyRowmans)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParseLffStandard)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParseLffUnicode)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadLffUnicode)->Unit(benchmark::kMillisecond);

}  // namespace
