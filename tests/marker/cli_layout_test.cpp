// The command line end to end, in-process: layout JSON, previews, and one-line errors with a
// non-zero exit that leave no file behind.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

using Result = test::CliResult;
const auto run = test::run_cli;

fs::path temp_file(const std::string& name) { return test::fresh_temp_file("marker_cli_test", name); }

TEST(CliLayout, JsonHasGlyphsWithElementsInMillimetres) {
  const Result r = run({"layout", "O1", "--height", "4", "--x", "-5", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["glyphs"].size(), 2u);
  EXPECT_EQ(j["glyphs"][0]["char"], "O");
  bool has_curve = false;
  for (const auto& e : j["glyphs"][0]["elements"]) {
    ASSERT_TRUE(e.contains("kind") && e.contains("laser") && e.contains("start") && e.contains("end"));
    if (e["kind"] == "arc") {
      has_curve = true;
      EXPECT_TRUE(e.contains("center") && e.contains("radius") && e.contains("ccw"));
    }
    if (e["kind"] == "ellipse") {
      has_curve = true;
      for (const char* k : {"center", "rx", "ry", "rotation_deg", "start_deg", "end_deg", "ccw"})
        EXPECT_TRUE(e.contains(k)) << k;
    }
  }
  EXPECT_TRUE(has_curve) << "the built-in O is drawn with arcs";
  // Cap height 4 mm: the figure is 4 mm tall (O may overshoot slightly).
  const double h = j["bounds_mm"]["y_max"].get<double>() - j["bounds_mm"]["y_min"].get<double>();
  EXPECT_NEAR(h, 4.0, 0.2);
  EXPECT_NEAR(j["bounds_mm"]["x_min"].get<double>(), -5.0, 1.0);
}

// The ellipse's angles are degrees, as their names say: the parametric point at start_deg and
// end_deg (rotated by rotation_deg about the centre) is the element's start and end point.
TEST(CliLayout, EllipseAnglesAreDegrees) {
  const Result r = run({"layout", "O", "--height", "4", "--width-factor", "0.6", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  int ellipses = 0;
  for (const auto& e : j["glyphs"][0]["elements"]) {
    if (e["kind"] != "ellipse") continue;
    ++ellipses;
    const double rad = M_PI / 180, rot = e["rotation_deg"].get<double>() * rad;
    const double cx = e["center"][0], cy = e["center"][1], rx = e["rx"], ry = e["ry"];
    for (const char* which : {"start", "end"}) {
      const double t = e[std::string(which) + "_deg"].get<double>() * rad;
      const double px = rx * std::cos(t), py = ry * std::sin(t);
      EXPECT_NEAR(cx + px * std::cos(rot) - py * std::sin(rot), e[which][0].get<double>(), 1e-9) << which;
      EXPECT_NEAR(cy + px * std::sin(rot) + py * std::cos(rot), e[which][1].get<double>(), 1e-9) << which;
    }
  }
  EXPECT_GT(ellipses, 0) << "a narrowed O is drawn with elliptical arcs";
}

TEST(CliLayout, PreviewWritesSvgAndPng) {
  for (const char* name : {"p.svg", "p.png"}) {
    const fs::path out = temp_file(name);
    const Result r = run({"preview", "SN 0042", "--height", "3", "-o", out.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_TRUE(fs::exists(out));
    EXPECT_GT(fs::file_size(out), 500u);
    EXPECT_FALSE(fs::exists(out.string() + ".part"));
    std::ifstream in(out, std::ios::binary);
    std::string head(8, '\0');
    in.read(head.data(), 8);
    if (out.extension() == ".png") {
      EXPECT_EQ(head.substr(1, 3), "PNG");
    } else {
      EXPECT_NE(head.find("<?xml"), std::string::npos);
    }
  }
}

// Each refusal is one line on stderr naming the problem, exit 1, and no file written.
TEST(CliLayout, RefusalsAreOneLineErrors) {
  const fs::path out = temp_file("refused.png");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"preview", "TOO WIDE FOR THE FIELD", "--height", "20", "-o", out.string()}, "leaves the field"},
      {{"preview", "X", "--font", "no-such-font", "-o", out.string()}, "unknown font 'no-such-font'"},
      {{"preview", "\xc3\xa9", "-o", out.string()}, "no glyph for 'é' (U+00E9)"},
      {{"preview", "AB", "--height", "-1", "-o", out.string()}, "marker: --height: -1 is outside the range 0.01 to 10000 mm"},
      {{"preview", "AB", "--circle", "0,0", "-o", out.string()}, "--circle '0,0'"},
      {{"preview", "AB", "-o", temp_file("x.jpg").string()}, "must end in .svg or .png"},
      {{"preview", "   ", "-o", out.string()}, "has nothing to mark"},
      {{"preview", "AB", "-o", "/nonexistent-dir/x.png"}, "/nonexistent-dir/x.png"},
  };
  for (const auto& [args, expected] : cases) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 1) << expected;
    EXPECT_NE(r.err.find(expected), std::string::npos) << "stderr: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(CliLayout, FontsListsBuiltinAndDebianFonts) {
  const Result r = run({"fonts"});
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("builtin"), std::string::npos);
  EXPECT_NE(r.out.find("rowmans"), std::string::npos);
  EXPECT_NE(r.out.find("standard  lff"), std::string::npos);
}

// The JSON lists the same fonts as the text, marks names several files share, and every font it
// calls unique opens by that name.
TEST(CliLayout, FontsJsonMarksSharedNames) {
  const Result r = run({"fonts", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_GE(j["fonts"].size(), 1u);
  EXPECT_EQ(j["fonts"][0]["name"], "builtin");
  EXPECT_GT(j["fonts"][0]["glyphs"].get<int>(), 90);
  const Result text = run({"fonts"});
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.out.begin(), text.out.end(), '\n')), j["fonts"].size());
  int checked = 0;
  for (const auto& f : j["fonts"]) {
    if (f["format"] != "jhf" || checked >= 3) continue;
    const std::string name = f["name"];
    const Result open = run({"layout", "H", "--font", name});
    EXPECT_EQ(open.code, f["unique"].get<bool>() ? 0 : 1) << name << ": " << open.err;
    ++checked;
  }
}

TEST(CliLayout, PreviewJsonDescribesWhatWasDrawn) {
  const fs::path out = temp_file("described.svg");
  const Result r = run({"preview", "AB\\nC", "--height", "4", "-o", out.string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["output"], out.string());
  EXPECT_EQ(j["text"], "AB\nC");
  EXPECT_EQ(j["glyphs"], 3);
  EXPECT_NEAR(j["bounds_mm"]["y_max"].get<double>(), 4.0, 0.2);
  EXPECT_TRUE(fs::exists(out));
  // The same figure as `layout --json`: its bounds and its lit length.
  const Result l = run({"layout", "AB\\nC", "--height", "4", "--json"});
  const auto fig = nlohmann::json::parse(l.out);
  EXPECT_DOUBLE_EQ(j["bounds_mm"]["x_min"].get<double>(), fig["bounds_mm"]["x_min"].get<double>());
  EXPECT_DOUBLE_EQ(j["bounds_mm"]["y_min"].get<double>(), fig["bounds_mm"]["y_min"].get<double>());
}

}  // namespace
}  // namespace mark
