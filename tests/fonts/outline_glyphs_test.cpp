// Outline fonts against hostile files (fixtures from tests/fonts/data/outline/make_fixtures.py):
// glyphs are made on first use and once per glyph index (65 502 code points pointing at one
// 2000-point glyph cost one fit), a glyph or a font over its element limit is refused naming the
// file, the character and the limit, one-point contours leave no laser-off move, every glyph of
// the installed outline fonts keeps the contract every loader keeps, fonts without glyphs or with
// an unusable height are refused naming the file, and a font shared by threads makes each glyph
// once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <thread>

#include "fonts/catalog.hpp"
#include "fonts/error.hpp"
#include "tests/error_of.hpp"
#include "fonts/loaders.hpp"
#include "fonts/loaders/outline_glyphs.hpp"
#include "fonts/loaders/read_font_file.hpp"
#include "loader_test_util.hpp"

namespace mark::test {
namespace {

const std::string kOutlineDir = kDataDir + "/outline";
const std::string kDejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const std::string kLiberation = "/usr/share/fonts/truetype/liberation2/LiberationSans-Regular.ttf";

loaders::OutlineGlyphs glyphs_of(const std::string& path, OutlineLimits limits = {}) {
  return loaders::OutlineGlyphs(loaders::read_font_file(path), path, kOutlineToleranceEm, limits);
}

TEST(OutlineGlyphs, NothingIsMadeUntilAskedAndThenOncePerGlyphIndex) {
  const loaders::OutlineGlyphs blob = glyphs_of(kOutlineDir + "/blob_65502.ttf");
  EXPECT_EQ(blob.code_point_count(), 65502u);
  EXPECT_EQ(blob.glyphs_made(), 0u);
  const Glyph* a = blob.find(U'A');
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(blob.glyphs_made(), 1u);
  // Every code point of the map is the same glyph, fitted once.
  for (char32_t cp = 0x21; cp <= 0xFFFE; cp += 61) EXPECT_EQ(blob.find(cp), a) << describe_code_point(cp);
  EXPECT_EQ(blob.find(0xFFFE), a);
  EXPECT_EQ(blob.glyphs_made(), 1u);
  EXPECT_EQ(blob.find(U' '), nullptr);  // U+0020 and U+FFFF are not in the map
  EXPECT_EQ(blob.find(0xFFFF), nullptr);
  EXPECT_EQ(blob.find(0x1F600), nullptr);  // beyond the BMP: never looked up
  const std::vector<char32_t> cps = blob.code_points();
  ASSERT_EQ(cps.size(), 65502u);
  EXPECT_EQ(cps.front(), char32_t{0x21});
  EXPECT_EQ(cps.back(), char32_t{0xFFFE});

  // A real font: marking "SN 42" makes five glyphs of its thousands.
  const loaders::OutlineGlyphs dejavu = glyphs_of(kDejaVu);
  EXPECT_GT(dejavu.code_point_count(), 3000u);
  for (char32_t cp : std::u32string(U"SN 42SN 42")) EXPECT_NE(dejavu.find(cp), nullptr);
  EXPECT_EQ(dejavu.glyphs_made(), 5u);
}

// Found by fuzz_outline_font: a format-4 map whose walk (FT_Get_Next_Char) reaches codes its
// lookup (FT_Get_Char_Index) does not find. Only what find() finds is listed and counted.
TEST(OutlineFont, AMalformedMapListsOnlyWhatLookupFinds) {
  const std::string path = std::string(MARKER_SOURCE_DIR) + "/tests/fuzz/seeds/outline_font/cmap_walk_disagrees.ttf";
  const StrokeFont f = load_outline_font(path);
  const std::vector<char32_t> cps = f.code_points();
  EXPECT_EQ(cps.size(), f.size());
  ASSERT_FALSE(cps.empty());
  int made = 0, refused = 0;
  for (char32_t cp : cps) {
    try {
      EXPECT_NE(f.find(cp), nullptr) << describe_code_point(cp);
      ++made;
    } catch (const FontFileError& e) {
      // Its glyphs are broken too: a refusal naming the file and the character, in FreeType's words.
      EXPECT_EQ(std::string(e.what()).rfind(path + ":0: glyph for " + describe_code_point(cp) + ": ", 0), 0u) << e.what();
      EXPECT_EQ(std::string(e.what()).find("FreeType error 0x"), std::string::npos) << e.what();
      ++refused;
    }
  }
  EXPECT_GT(made, 0);
  EXPECT_GT(refused, 0);
}

TEST(OutlineFont, OpeningMakesOnlyTheGlyphsItMeasuresHeightsOn) {
  // With a font budget of exactly what 'H', 'x' and the space hold, the font still opens (so
  // opening made no other glyph) and the next glyph is refused by the budget.
  const StrokeFont full = load_outline_font(kDejaVu);
  const std::size_t measured =
      full.glyph(U'H').elements.size() + full.glyph(U'x').elements.size() + full.glyph(U' ').elements.size();
  const StrokeFont tight = load_outline_font(kDejaVu, nullptr, kOutlineToleranceEm, {20'000, measured});
  EXPECT_EQ(tight.metrics().cap_height, full.metrics().cap_height);
  EXPECT_EQ(tight.glyph(U'H').elements.size(), full.glyph(U'H').elements.size());
  const std::size_t with_a = full.glyph(U'A').elements.size();
  EXPECT_EQ(error_of([&] { tight.find(U'A'); }),
            kDejaVu + ":0: glyph for 'A' (U+0041): " + std::to_string(with_a) + " elements would make the font hold " +
                std::to_string(measured + with_a) + ", more than its limit of " + std::to_string(measured));
  // A refusal stays a refusal, and glyphs already made stay usable.
  EXPECT_THROW(tight.find(U'A'), FontFileError);
  EXPECT_NE(tight.find(U'x'), nullptr);
}

TEST(OutlineFont, AGlyphOverItsLimitIsRefusedNamingFileCharacterAndLimit) {
  const std::string path = kOutlineDir + "/blob_1.ttf";
  const StrokeFont whole = load_outline_font(path);
  const std::size_t n = whole.glyph(U'A').elements.size();
  ASSERT_GT(n, 1000u);  // 1000 quadratic Béziers, each at least one arc
  const StrokeFont limited = load_outline_font(path, nullptr, kOutlineToleranceEm, {n - 1, OutlineLimits{}.font_elements});
  const std::string expected = path + ":0: glyph for 'A' (U+0041): more than " + std::to_string(n - 1) +
                               " elements, the limit for one glyph";
  EXPECT_EQ(error_of([&] { limited.find(U'A'); }), expected);
  EXPECT_EQ(error_of([&] { limited.glyph(U'A'); }), expected);
  const StrokeFont at_limit = load_outline_font(path, nullptr, kOutlineToleranceEm, {n, OutlineLimits{}.font_elements});
  EXPECT_EQ(at_limit.glyph(U'A').elements.size(), n);
}

TEST(OutlineFont, OnePointContoursDrawNothingAndLeaveNoLaserOffMove) {
  const StrokeFont f = load_outline_font(kOutlineDir + "/one_point_contours.ttf");
  const auto count = [](const Glyph& g, bool lit) {
    return std::count_if(g.elements.begin(), g.elements.end(), [&](const Element& e) { return e.laser() == lit; });
  };
  // 'A': a square, then a one-point contour; 'B': two one-point contours, then a square.
  for (char32_t cp : {U'A', U'B'}) {
    const Glyph& g = f.glyph(cp);
    EXPECT_EQ(count(g, true), 4) << describe_code_point(cp);
    EXPECT_EQ(count(g, false), 0) << describe_code_point(cp);
    EXPECT_EQ(g.bounds().min, Point(100, 0));
    EXPECT_EQ(g.bounds().max, Point(500, 700));
  }
  // 'C': square, one-point contour, square: one move, from the first square's end to the second's start.
  const Glyph& c = f.glyph(U'C');
  ASSERT_EQ(c.elements.size(), 9u);
  EXPECT_FALSE(c.elements[4].laser());
  EXPECT_EQ(c.elements[4].start(), c.elements[3].end());
  EXPECT_EQ(c.elements[4].end(), c.elements[5].start());
  EXPECT_EQ(c.elements[5].start(), Point(500, 0));
  // 'D': only a one-point contour: an empty glyph that still advances.
  EXPECT_TRUE(f.glyph(U'D').elements.empty());
  EXPECT_EQ(f.glyph(U'D').advance, 900);
}

// The contract every loader keeps (tests/fuzz/fuzz_font.hpp), as test assertions.
void expect_contract(const Glyph& g, const std::string& what) {
  const auto& els = g.elements;
  if (els.empty()) return;
  EXPECT_TRUE(els.front().laser()) << what << " starts with a laser-off move";
  EXPECT_TRUE(els.back().laser()) << what << " ends with a laser-off move";
  for (std::size_t i = 0; i < els.size(); ++i) {
    if (els[i].laser()) {
      EXPECT_GT(els[i].length(), 0) << what << " element " << i;
    }
    if (i == 0) continue;
    EXPECT_FALSE(!els[i].laser() && !els[i - 1].laser()) << what << " two laser-off moves at " << i;
    EXPECT_LT((els[i].start() - els[i - 1].end()).norm(), 1e-6) << what << " gap at " << i;
  }
}

// The installed DejaVu Sans and Liberation Sans and every fixture a loader accepts: one test
// per font, so a sharded run (scripts/asan.sh) spreads the two large fonts over its processes.
std::vector<std::string> contract_fonts() {
  std::vector<std::string> fonts = {kDejaVu, kLiberation};
  std::vector<std::string> fixtures;
  for (const auto& entry : std::filesystem::directory_iterator(kOutlineDir)) {
    const std::string stem = entry.path().stem().string();
    const bool refused = stem.find("height") != std::string::npos || stem == "no_glyphs";
    if ((entry.path().extension() == ".ttf" || entry.path().extension() == ".otf") && !refused)
      fixtures.push_back(entry.path().string());
  }
  std::sort(fixtures.begin(), fixtures.end());  // the directory's order is the file system's
  fonts.insert(fonts.end(), fixtures.begin(), fixtures.end());
  return fonts;
}

class EveryGlyph : public testing::TestWithParam<std::string> {};

TEST_P(EveryGlyph, KeepsTheContract) {
  const std::string& path = GetParam();
  const StrokeFont f = load_outline_font(path);
  std::size_t largest = 0, total = 0;
  std::set<const Glyph*> made;
  for (char32_t cp : f.code_points()) {
    const Glyph& g = f.glyph(cp);
    if (!made.insert(&g).second) continue;  // a glyph shared by several code points: checked once
    expect_contract(g, path + " " + describe_code_point(cp));
    largest = std::max(largest, g.elements.size());
    total += g.elements.size();
    if (HasFailure()) return;
  }
  std::printf("%s: %zu code points, %zu glyphs made, %zu elements, largest glyph %zu\n", path.c_str(),
              f.size(), made.size(), total, largest);
}

INSTANTIATE_TEST_SUITE_P(RealAndFixtureFonts, EveryGlyph, testing::ValuesIn(contract_fonts()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = std::filesystem::path(info.param).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(OutlineFont, FontsWithoutGlyphsOrAUsableHeightAreRefusedNamingTheFile) {
  const std::string range = "is no usable standard height (allowed 0.01 .. 10 em)";
  for (const auto& [name, message] :
       {std::pair<std::string, std::string>{"no_glyphs", "the font maps no character of the Basic Multilingual Plane to a glyph"},
        {"zero_height", "cap height 0 font units (0 em) " + range},
        {"negative_height", "cap height -100 font units (-0.1 em) " + range},
        {"absurd_height", "cap height 16000 font units (1000 em) " + range}}) {
    const std::string path = kOutlineDir + "/" + name + ".ttf";
    EXPECT_EQ(error_of([&] { load_outline_font(path); }), path + ":0: " + message);
    EXPECT_EQ(error_of([&] { open_font(path); }), path + ":0: " + message);
  }
}

TEST(OutlineFont, ASharedFontMakesEachGlyphOnceAcrossThreads) {
  const auto font = open_font(kDejaVu);
  const std::u32string text = U"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  std::vector<std::vector<const Glyph*>> seen(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t)
    threads.emplace_back([&, t] {
      // Each thread walks the text from its own place, so they ask for different glyphs at once.
      for (std::size_t i = 0; i < text.size(); ++i) seen[t].push_back(font->find(text[(i + t * 17) % text.size()]));
    });
  for (std::thread& t : threads) t.join();
  for (std::size_t t = 1; t < seen.size(); ++t)
    for (std::size_t i = 0; i < text.size(); ++i)
      EXPECT_EQ(seen[t][i], seen[0][(i + t * 17) % text.size()]) << "thread " << t << " index " << i;
}

}  // namespace
}  // namespace mark::test
