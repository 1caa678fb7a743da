// A part is good only when it is verified (issue 20): a code that does not read back off the
// mark makes the part `rejected` — recorded so in the audit log, its numbers void and never issued
// again, the run stopped with exit status 2 — while the same job at a speed whose code reads ends
// `done` and goes on from the next number.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/error.hpp"
#include "marker/production/job_file.hpp"
#include "marker/production/part_verdict.hpp"
#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

// A Data Matrix of dots on SL14: at 1000 mm/s the dots are too small to read (coverage 14 %,
// no reader decodes it); squares at 300 mm/s read.
std::string code_job(double speed_mm_s, const std::string& style) {
  std::ostringstream j;
  j << R"({"format": "marker-job/1", "head": "SL14", "counters": {"serial": {"start": 41, "width": 6}},
           "pens": {"code": {"speed_mm_s": )"
    << speed_mm_s << R"(}}, "objects": [{"name": "udi", "kind": "code", "pen": "code",
           "symbology": "datamatrix", "template": "SN{serial}", "module_mm": 0.25, "style": ")"
    << style << R"("}]})";
  return j.str();
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(PartVerdict, AnyCodeThatDoesNotDecodeToItsDataRejectsThePartNamingIt) {
  CodeVerification read, unread, misread;
  read.decoded = read.data_match = true;
  unread.decided_by = "any two";
  unread.modules_wrong = 113;
  misread.decoded = true;
  misread.decoded_data = "SN41";
  misread.expected_data = "SN42";
  const JobSpec spec;
  const auto marked = [](std::vector<CodeVerification> codes) {
    JobResult r;
    r.codes = std::move(codes);
    return r;
  };
  const JobResult none = marked({}), one = marked({read}), second_unread = marked({read, unread}),
                  wrong = marked({misread});
  EXPECT_FALSE(part_verdict({{&spec, &none, {}}, {&spec, &one, {}}}));
  const auto r = part_verdict({{&spec, &one, {}}, {&spec, &second_unread, {}}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->object, 1u);
  EXPECT_EQ(r->reason, "code 2 not decoded by any two (modules wrong: 113)");
  EXPECT_EQ(part_verdict({{&spec, &wrong, {}}})->reason, "code 1 read as \"SN41\", not \"SN42\" (modules wrong: 0)");
}

TEST(PartVerdict, AnObjectBelowItsRequiredQualityIsRejectedNamingTheClass) {
  // Quality figures of a mark: 55 µm off at worst, the raster hatch's "poor" of issue 23.
  JobResult poor;
  poor.quality = Quality{};
  poor.quality->lit_points = 1000;
  poor.quality->max_deviation_um = 55;
  poor.quality->coverage = 0.99;
  poor.quality->dose_ratio_max = 1.67;
  poor.quality->dose_per_mm_fraction = 1;  // the pen's nominal energy per mm
  const JobSpec spec;
  MarkRequirement good;
  good.quality = QualityClass::good;
  EXPECT_FALSE(part_verdict({{&spec, &poor, {}}})) << "nothing required: nothing judged but the codes";
  const auto r = part_verdict({{&spec, &poor, good}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->reason, "quality poor, below good (max deviation 55.0 µm, coverage 99.00 %, dose ratio 1.67, dose per mm 100 % of the pen's)");
  // Within "good"'s limits (30 µm, 98 %, dose ratio 2): met.
  poor.quality->max_deviation_um = 25;
  EXPECT_FALSE(part_verdict({{&spec, &poor, good}}));
  // Most strokes unlit: the dose ratio's median is 0 and its value a sentinel; the words say so.
  poor.quality->coverage = 0.3;
  poor.quality->dose_ratio_max = 1e9;
  EXPECT_EQ(part_verdict({{&spec, &poor, good}})->reason,
            "quality poor, below good (max deviation 25.0 µm, coverage 30.00 %, most of the strokes got no dose, dose per mm 100 % of the pen's)");
  // Pulses 60 µm apart on a 40 µm spot's line: a gap of half a spot is "good"'s limit.
  poor.quality->coverage = 0.99;
  poor.quality->dose_ratio_max = 1.2;
  poor.quality->spot_diameter_um = 40;
  poor.quality->pulse_gap_max_um = 20;
  EXPECT_FALSE(part_verdict({{&spec, &poor, good}}));
  poor.quality->pulse_gap_max_um = 21;
  EXPECT_EQ(part_verdict({{&spec, &poor, good}})->reason,
            "quality poor, below good (max deviation 25.0 µm, coverage 99.00 %, dose ratio 1.20, pulse gap "
            "21.0 µm (spot 40 µm), dose per mm 100 % of the pen's)");
  // A stroke at 45 % of the pen's energy per mm: below "good"'s half.
  poor.quality->pulse_gap_max_um = 0;
  poor.quality->dose_per_mm_fraction = 0.45;
  EXPECT_EQ(part_verdict({{&spec, &poor, good}})->reason,
            "quality poor, below good (max deviation 25.0 µm, coverage 99.00 %, dose ratio 1.20, pulse gap "
            "0.0 µm (spot 40 µm), dose per mm 45 % of the pen's)");
  // A device without an evaluator gives no figures: nothing to fall short of.
  const JobResult blind;
  EXPECT_FALSE(part_verdict({{&spec, &blind, good}}));
}

TEST(PartRejected, ACodeThatDoesNotReadIsRejectedItsNumberVoidAndTheRunStops) {
  const fs::path dir = test::fresh_temp_dir("marker_part_rejected");
  const std::string store = (dir / "s.sqlite").string();
  const fs::path bad = write(dir, "bad.json", code_job(1000, "dot"));
  const test::CliResult r = test::run_cli({"mark", "--job", bad.string(), "--count", "3", "--store", store,
                                           "--create-counters", "--virtual-time", "--json"});
  EXPECT_EQ(r.code, 2) << r.err;
  // One part, not three: the run stops at the rejected one.
  std::istringstream lines(r.out);
  std::string line;
  std::vector<nlohmann::json> parts;
  while (std::getline(lines, line)) parts.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(parts.size(), 1u) << r.out;
  EXPECT_EQ(parts[0]["outcome"], "rejected");
  EXPECT_EQ(parts[0]["objects"][0]["outcome"], "done");  // the device marked it all
  EXPECT_FALSE(parts[0]["objects"][0]["codes"][0]["data_match"].get<bool>());
  EXPECT_NE(parts[0]["message"].get<std::string>().find("object \"udi\": code 1 not decoded"), std::string::npos);
  EXPECT_NE(r.err.find("rejected: object \"udi\""), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("its numbers are void (serial=41)"), std::string::npos) << r.err;

  // The same code in squares at 300 mm/s reads: done, and the next number is 42 (41 stays void).
  const fs::path good = write(dir, "good.json", code_job(300, "square"));
  const test::CliResult g = test::run_cli({"mark", "--job", good.string(), "--count", "2", "--store", store,
                                           "--virtual-time", "--json"});
  EXPECT_EQ(g.code, 0) << g.err;
  std::istringstream good_lines(g.out);
  std::vector<std::int64_t> serials;
  while (std::getline(good_lines, line)) {
    const nlohmann::json p = nlohmann::json::parse(line);
    EXPECT_EQ(p["outcome"], "done");
    serials.push_back(p["serials"]["serial"].get<std::int64_t>());
  }
  EXPECT_EQ(serials, (std::vector<std::int64_t>{42, 43}));

  // The audit log says so, row by row.
  const test::CliResult log = test::run_cli({"log", "--store", store, "--json"});
  ASSERT_EQ(log.code, 0) << log.err;
  std::istringstream rows(log.out);
  std::vector<std::string> outcomes;
  while (std::getline(rows, line)) {
    const nlohmann::json row = nlohmann::json::parse(line);
    if (row["kind"] == "mark") outcomes.push_back(row["outcome"].get<std::string>());
  }
  EXPECT_EQ(outcomes, (std::vector<std::string>{"rejected", "done", "done"}));
  fs::remove_all(dir);
}


// A text whose pen the simulator says marks "poor": 1 mm letters at 5 m/s on SL10 (the lag rounds
// every letter off); at 300 mm/s and 3 mm they are "high".
std::string text_job(double speed_mm_s, double height_mm, const std::string& require) {
  std::ostringstream j;
  j << R"({"format": "marker-job/1", "head": "SL10", "counters": {"serial": {"start": 41, "width": 6}},
           "pens": {"p": {"speed_mm_s": )"
    << speed_mm_s << R"(}}, "objects": [{"name": "sn", "template": "SN {serial}", "height_mm": )" << height_mm
    << R"(, "require": )" << require << "}]}";
  return j.str();
}

TEST(PartRequire, APartTheSimulatorPredictsBelowItsRequiredQualityIsRefusedBeforeFiringConsumingNothing) {
  const fs::path dir = test::fresh_temp_dir("marker_part_require");
  const std::string store = (dir / "s.sqlite").string();
  const fs::path fast = write(dir, "fast.json", text_job(5000, 1, R"({"quality": "good"})"));
  const test::CliResult r = test::run_cli({"mark", "--job", fast.string(), "--count", "2", "--store", store,
                                           "--create-counters", "--virtual-time", "--json"});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << "no part was marked: " << r.out;
  EXPECT_NE(r.err.find("objects[0] \"sn\": the simulator predicts quality poor, below good (max deviation"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("(\"require\"); nothing was fired"), std::string::npos) << r.err;

  // Without the requirement the same job marks (and reports "poor"); with it at a pen that holds,
  // the first part takes 41: the refused part consumed nothing.
  const fs::path slow = write(dir, "slow.json", text_job(300, 3, R"({"quality": "high", "code": "read"})"));
  const test::CliResult g = test::run_cli({"mark", "--job", slow.string(), "--count", "1", "--store", store,
                                           "--virtual-time", "--json"});
  ASSERT_EQ(g.code, 0) << g.err;
  const nlohmann::json part = nlohmann::json::parse(g.out);
  EXPECT_EQ(part["outcome"], "done");
  EXPECT_EQ(part["serials"]["serial"].get<std::int64_t>(), 41);
  fs::remove_all(dir);
}

TEST(PartRequire, TheJobFileSaysWhatAnObjectRequiresInTheSameWordsAsTheCommandLine) {
  const auto refused = [](const std::string& require) {
    try {
      parse_job(text_job(300, 3, require), "j.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refused(R"({"quality": "good", "code": "read"})"), "");
  EXPECT_EQ(refused(R"({"quality": "poor"})"), "j.json: objects[0].require.quality: \"poor\" is not one of high, good");
  EXPECT_EQ(refused(R"({"code_grade": "B"})"), "j.json: objects[0].require.code_grade: a text object carries no code to grade");
  EXPECT_EQ(refused(R"({"qualty": "good"})").substr(0, 30), "j.json: objects[0].require.qua");
  const JobFile job = parse_job(code_job(300, "square").insert(0, ""), "c.json");
  EXPECT_FALSE(job.objects[0].require.any());
}

}  // namespace
}  // namespace mark
