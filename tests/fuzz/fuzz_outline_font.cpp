// libFuzzer target for outline fonts (TrueType and CFF/OpenType through FreeType,
// parse_outline_font): every input either throws InputError naming the source, or opens a font
// with finite, usable metrics whose glyphs keep the contract every loader keeps (fuzz_font.hpp)
// — checked on the first kGlyphsChecked code points, each glyph made on first use. A glyph over
// its limit is a reported refusal (FontFileError), not a bug; an input that costs more than its
// limits allow (a bomb that gets past them) fails the run as a timeout or out-of-memory
// (scripts/fuzz.sh runs with -timeout and -rss_limit_mb).
// Seeds: the fonts of tests/fonts/data/outline/ but the blob fonts (make_fixtures.py).
#include <set>
#include <string>

#include "fonts/error.hpp"
#include "fuzz_font.hpp"

namespace {

// Fitting is what an input costs (with coverage and the sanitizers, about 50 µs an element), so
// each input is checked on few glyphs, fitted to a hundredth of the default precision, within limits
// far below the defaults: more inputs a second, each well inside the time limit. The code paths
// are the ones the defaults take; only the numbers are smaller.
constexpr std::size_t kGlyphsChecked = 8;
constexpr double kToleranceEm = 100 * mark::kOutlineToleranceEm;
constexpr mark::OutlineLimits kLimits{500, 2'000};
const char* const kSource = "fuzz.ttf";

void check(const mark::StrokeFont& font) {
  using namespace mark;
  fuzz::check_metrics(font);
  const std::vector<char32_t> cps = font.code_points();
  if (cps.size() != font.size()) fuzz::broken("code_points() and size() disagree", 0);
  std::set<const Glyph*> checked;  // code points sharing a glyph: checked once
  for (std::size_t i = 0; i < cps.size() && i < kGlyphsChecked; ++i) {
    const char32_t cp = cps[i];
    try {
      const Glyph* g = font.find(cp);
      if (!g) fuzz::broken("a mapped code point has no glyph", cp);
      if (font.find(cp) != g) fuzz::broken("a glyph was made twice", cp);
      if (!checked.insert(g).second) continue;
      const Box b = g->bounds();
      const double size = b.empty() ? 1.0 : std::max({1.0, b.width(), b.height()});
      fuzz::check_glyph(*g, cp, 1e-6 * size);
    } catch (const FontFileError& e) {
      if (std::string(e.what()).rfind(kSource, 0) != 0) fuzz::broken("glyph error does not name the source", cp);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    check(mark::parse_outline_font(std::string(reinterpret_cast<const char*>(data), size), kSource, nullptr,
                                   kToleranceEm, kLimits));
  } catch (const mark::InputError& e) {
    if (std::string(e.what()).rfind(kSource, 0) != 0) mark::fuzz::broken("error does not name the source", 0);
  }
  return 0;
}
