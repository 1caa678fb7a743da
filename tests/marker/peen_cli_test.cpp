// `marker peen` end to end, in-process: JSON for the chosen planner, the side-by-side comparison,
// exports and previews written, gantry options taking effect, and one-line errors.
#include <gtest/gtest.h>

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
const auto run_peen = test::run_cli;

fs::path temp_file(const std::string& name) { return test::fresh_temp_file("marker_peen_cli_test", name); }

TEST(PeenCli, JsonForTheChosenPlanner) {
  const Result r = run_peen({"peen", "AB12-345678C", "--height", "3.175", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["planner"], "optimized");
  EXPECT_EQ(j["characters"], 12);
  EXPECT_EQ(j["dots"], j["strikes"]);
  EXPECT_GT(j["dots"].get<int>(), 12 * 5);
  EXPECT_NEAR(j["time_per_char_s"].get<double>() * 12, j["time_s"].get<double>(), 1e-9);
  EXPECT_NEAR(j["time_s"].get<double>(),
              j["move_time_s"].get<double>() + j["strike_time_s"].get<double>(), 1e-9);
  EXPECT_GT(j["travel_mm"].get<double>(), 0);
  EXPECT_NEAR(j["pitch_mm"].get<double>(), 3.175 / 6, 1e-12);
  EXPECT_EQ(j["gantry"]["steps_per_mm"]["x"], 40.0);
  EXPECT_FALSE(j.contains("compare"));
}

TEST(PeenCli, CompareRunsAllThreeUnderOneModel) {
  const Result r = run_peen({"peen", "8888888", "--font", "10x16", "--height", "12", "--align",
                        "center", "--y", "-6", "--window", "63x38", "--compare", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["compare"].size(), 3u);
  EXPECT_EQ(j["compare"][0]["planner"], "snake");
  EXPECT_EQ(j["compare"][1]["planner"], "block");
  EXPECT_EQ(j["compare"][2]["planner"], "optimized");
  const double snake = j["compare"][0]["time_s"], block = j["compare"][1]["time_s"],
               ours = j["compare"][2]["time_s"];
  EXPECT_LT(block, snake);
  EXPECT_LT(ours, 0.85 * block);
  EXPECT_EQ(j["time_s"], j["compare"][2]["time_s"]);
  EXPECT_NEAR(j["window_mm"]["x_max"].get<double>(), 31.5, 1e-12);
  // The text table has a header and one row per planner.
  const Result t =
      run_peen({"peen", "8888888", "--font", "10x16", "--height", "12", "--align", "center", "--compare"});
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NE(t.out.find("snake"), std::string::npos);
  EXPECT_NE(t.out.find("block"), std::string::npos);
  EXPECT_NE(t.out.find("optimized"), std::string::npos);
}

TEST(PeenCli, GantryOptionsChangeTheTime) {
  auto time = [](std::vector<std::string> extra) {
    std::vector<std::string> args = {"peen", "H", "--planner", "block", "--json"};
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = run_peen(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const auto base = time({});
  const auto slow = time({"--strike-ms", "25"});
  // 5x7 "H": 2·7 + 3 = 17 dots, each 20 ms longer.
  EXPECT_NEAR(slow["time_s"].get<double>() - base["time_s"].get<double>(), 17 * 0.020, 1e-9);
  const auto y_only = time({"--y-accel", "12000"});  // four times the acceleration on Y
  EXPECT_LT(y_only["time_s"].get<double>(), base["time_s"].get<double>());
  EXPECT_EQ(y_only["gantry"]["accel_mm_s2"]["x"], 3000.0);
  EXPECT_EQ(y_only["gantry"]["accel_mm_s2"]["y"], 12000.0);
}

TEST(PeenCli, WritesCsvGcodeAndPreview) {
  const fs::path csv = temp_file("plan.csv"), ngc = temp_file("plan.ngc"), svg = temp_file("plan.svg");
  for (const auto& [out, extra] : {std::pair{csv, "-o"}, std::pair{ngc, "-o"}, std::pair{svg, "--preview"}}) {
    const Result r = run_peen({"peen", "VIN-7", "--font", "7x9", extra, out.string()});
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_TRUE(fs::exists(out)) << out;
    EXPECT_GT(fs::file_size(out), 100u);
  }
  std::ifstream in(ngc);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "%");
}

TEST(PeenCli, StrokeFontsBecomeContinuousDots) {
  const Result r = run_peen({"peen", "SN 42", "--font", "builtin", "--height", "4", "--pitch", "0.4", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["characters"], 4);  // the space has no dots
  EXPECT_DOUBLE_EQ(j["pitch_mm"].get<double>(), 0.4);
  // Dots at most a pitch apart along every stroke: at least length / pitch of them, and no more
  // than one per pitch plus both ends of every element.
  const fs::path svg = temp_file("sn42.svg");
  const Result layout = run_peen({"preview", "SN 42", "--height", "4", "--align", "center", "-o", svg.string(), "--json"});
  ASSERT_EQ(layout.code, 0) << layout.err;
  const auto l = nlohmann::json::parse(layout.out);
  const double per_pitch = l["mark_length_mm"].get<double>() / 0.4;
  EXPECT_GE(j["dots"].get<double>(), per_pitch);
  EXPECT_LE(j["dots"].get<double>(), per_pitch + l["elements"].get<double>() + 1);
}

// With its defaults (5x7, 5 mm, centred) an ordinary 12-character text fits the field, centred.
TEST(PeenCli, DefaultsFitOrdinaryText) {
  const Result r = run_peen({"peen", "ABCDEFGHIJKL", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["characters"], 12);
  // Pitch 5/6 mm; each character advances 6 pitches (5 columns and a gap), centred: the line of
  // 72 pitches starts at −36; the dots run from A's first column to L's fifth, 70 pitches.
  const double pitch = 5.0 / 6;
  const auto& w = j["window_mm"];
  EXPECT_NEAR(w["x_min"].get<double>(), -36 * pitch, 1e-9);
  EXPECT_NEAR(w["x_max"].get<double>(), 34 * pitch, 1e-9);
}

TEST(PeenCli, BadInputIsOneLineAndExitOne) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"peen", "abc"},                                 // no lower case in 5x7
        {"peen", "AB", "--window", "2x2"},                                        // text leaves it
        {"peen", "AB", "--window", "sixty"},                                      // malformed
        {"peen", "AB", "--accel", "-5"},                                          // impossible gantry
        {"peen", "AB", "--pitch", "0", "--font", "builtin"},                      // impossible pitch
        {"peen", "AB", "-o", temp_file("plan.pdf").string()},                     // unknown format
        {"peen", "AB", "--font", "10x16", "--height", "300"}}) {                  // leaves the field
    const Result r = run_peen(args);
    EXPECT_EQ(r.code, 1) << args[1] << " " << (args.size() > 2 ? args[2] : "");
    EXPECT_EQ(r.err.rfind("marker: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(temp_file("plan.pdf")));
}

}  // namespace
}  // namespace mark
