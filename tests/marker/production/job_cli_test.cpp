// The production commands end to end through the command line: job new → job check, serial
// reserve / set / show, log as JSON Lines and CSV, and their one-line refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

using test::run_cli;

struct JobCli : testing::Test {
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("marker-job-cli-" + std::to_string(::getpid()));
  std::string job = (dir / "bracket.json").string();
  std::filesystem::path state;
  void SetUp() override {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    state = test::use_station_state(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
};

TEST_F(JobCli, NewThenCheckRoundTrip) {
  auto r = run_cli({"job", "new", "-o", job, "--text", "SN {serial} LOT {var:lot}", "--width", "6",
                    "--start", "41", "--height", "3", "--power", "80", "--frequency", "40",
                    "--speed", "800", "--var", "lot=A00"});
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_cli({"job", "check", job, "--json", "--set", "lot=B17"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["objects"].size(), 1u);
  EXPECT_EQ(j["objects"][0]["text"], "SN 000041 LOT B17");
  EXPECT_EQ(j["serials"]["serial"], 41);
  // 800 mm/s at 40 kHz: pulses 20 µm apart, half the 40 µm spot overlapping.
  EXPECT_DOUBLE_EQ(j["objects"][0]["pulse_spacing_um"].get<double>(), 20.0);
  EXPECT_DOUBLE_EQ(j["objects"][0]["pulse_overlap_fraction"].get<double>(), 0.5);
  EXPECT_EQ(j["objects"][0]["glyphs"], 17);
  // Checking wrote nothing: no store.
  EXPECT_FALSE(std::filesystem::exists(state));
  // An existing file is not replaced without --force.
  r = run_cli({"job", "new", "-o", job, "--text", "X"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: " + job + " exists; give --force to replace it\n");
}

// `job new` writes only what `job check` accepts: a text that leaves the field is refused with
// check's own words and no file; the same object moved there by hand is refused by check.
TEST_F(JobCli, CheckRefusesAJobThatLeavesTheField) {
  const auto n = run_cli({"job", "new", "-o", job, "--text", "{serial}", "--height", "3", "--x", "54"});
  EXPECT_EQ(n.code, 1);
  EXPECT_EQ(n.err.rfind("marker: " + job + ": objects[0] \"text\": the text layout leaves the field", 0), 0u) << n.err;
  EXPECT_NE(n.err.find("(nothing written)\n"), std::string::npos) << n.err;
  EXPECT_FALSE(std::filesystem::exists(job));
  ASSERT_EQ(run_cli({"job", "new", "-o", job, "--text", "{serial}", "--height", "3"}).code, 0);
  nlohmann::json j = nlohmann::json::parse(std::ifstream(job));
  j["objects"][0]["x_mm"] = 54;
  std::ofstream(job) << j.dump(2);
  const auto r = run_cli({"job", "check", job});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err.rfind("marker: " + job + ": objects[0] \"text\": the text layout leaves the field", 0), 0u) << r.err;
}

TEST_F(JobCli, SerialAdministrationAndLog) {
  ASSERT_EQ(run_cli({"job", "new", "-o", job, "--text", "SN {serial}", "--width", "6"}).code, 0);
  // A counter exists only once created; showing it reads, never creates.
  auto r = run_cli({"serial", "show", "serial", "--job", job, "--json"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(state / "serials.sqlite"));
  r = run_cli({"serial", "create", "serial", "--job", job, "--station", "s1"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "counter serial created: next value 1\n");
  EXPECT_EQ(r.err, "marker: store sqlite:" + (state / "serials.sqlite").string() + "\n");
  r = run_cli({"serial", "create", "serial", "--job", job});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("has this counter already (next value 1)"), std::string::npos) << r.err;
  r = run_cli({"serial", "show", "serial", "--job", job, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["next"], 1);
  EXPECT_TRUE(nlohmann::json::parse(r.out)["highest_issued"].is_null());
  EXPECT_EQ(nlohmann::json::parse(r.out)["store"], "sqlite:" + (state / "serials.sqlite").string());
  r = run_cli({"serial", "reserve", "serial", "3", "--job", job, "--station", "s1", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["reserved"], nlohmann::json({1, 2, 3}));
  r = run_cli({"serial", "set", "serial", "2", "--job", job});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: store sqlite:" + (state / "serials.sqlite").string() +
                       "\nmarker: serial set serial 2: refused, 3 was already issued in this period (a "
                       "number is never issued twice); the next value is at least 4\n");
  ASSERT_EQ(run_cli({"serial", "set", "serial", "500", "--job", job, "--station", "s1"}).code, 0);
  r = run_cli({"serial", "show", "serial", "--job", job, "--json"});
  EXPECT_EQ(nlohmann::json::parse(r.out)["next"], 500);
  EXPECT_EQ(nlohmann::json::parse(r.out)["highest_issued"], 3);
  r = run_cli({"log", "--job", job, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream lines(r.out);
  std::vector<nlohmann::json> rows;
  for (std::string line; std::getline(lines, line);) rows.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0]["kind"], "create");
  EXPECT_EQ(rows[1]["serials"]["serial"], 1);
  EXPECT_EQ(rows[1]["outcome"], "reserved");
  EXPECT_EQ(rows[1]["values"], nlohmann::json::parse(R"([{"counter":"serial","value":1,"period":"","cycle":0,"repeat":0}])"));
  EXPECT_EQ(rows[4]["kind"], "set");
  EXPECT_EQ(rows[4]["station"], "s1");
  EXPECT_EQ(rows[4]["job_sha256"].get<std::string>().size(), 64u);
  r = run_cli({"log", "--job", job, "--csv", "--since", "1h"});
  EXPECT_EQ(r.out.substr(0, 15), "id,time_utc,sta");
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 6);
  r = run_cli({"log", "--job", job, "--since", "tomorrow"});
  EXPECT_EQ(r.code, 1);
  r = run_cli({"log", "--store", (dir / "none.sqlite").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos);
}

}  // namespace
}  // namespace mark
