// Objects of a job meet only in the part (issue 20): a Data Matrix moved onto the job's text, or
// two texts laid over each other, passed `job check` and marked "done" because each object was
// compiled and read back alone. Now both are refused at `job check` and before every part (inside
// its allocation: nothing consumed), naming both objects and where; objects apart pass.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

// "SN 000041" in 3 mm builtin letters from (-10, 4) and a second object at `second`.
std::string job_with(const std::string& second) {
  return R"({"format": "marker-job/1", "head": "SL10", "counters": {"serial": {"start": 41, "width": 6}},
    "pens": {"p": {"speed_mm_s": 300}},
    "objects": [{"name": "sn", "template": "SN {serial}", "height_mm": 3, "x_mm": -10, "y_mm": 4}, )" +
         second + "]}";
}

constexpr const char* kCodeOnTheText =
    R"({"name": "udi", "kind": "code", "symbology": "datamatrix", "template": "{serial}", "module_mm": 0.3,
        "x_mm": -5, "y_mm": 5})";
constexpr const char* kCodeBelow =
    R"({"name": "udi", "kind": "code", "symbology": "datamatrix", "template": "{serial}", "module_mm": 0.3,
        "x_mm": -5, "y_mm": -6})";
// The same text 0.5 mm higher: its strokes cross the first's.
constexpr const char* kTextOver = R"({"name": "lot", "template": "LOT 7", "height_mm": 3, "x_mm": -10, "y_mm": 4.5})";
constexpr const char* kTextApart = R"({"name": "lot", "template": "LOT 7", "height_mm": 3, "x_mm": -10, "y_mm": -2})";

struct Scratch {
  fs::path dir;
  std::string store;
  explicit Scratch(const char* name) : dir(test::fresh_temp_dir(name)), store((dir / "s.sqlite").string()) {}
  ~Scratch() { fs::remove_all(dir); }
  std::string file(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  }
  test::CliResult check(const std::string& job) const { return test::run_cli({"job", "check", job}); }
  test::CliResult mark(const std::string& job) const {
    return test::run_cli({"mark", "--job", job, "--store", store, "--create-counters", "--virtual-time", "--json"});
  }
};

TEST(ObjectClearance, ACodeOnTheTextIsRefusedAtJobCheckAndBeforeThePartNamingBoth) {
  const Scratch run("marker_clearance_code");
  const std::string bad = run.file("bad.json", job_with(kCodeOnTheText));
  const test::CliResult c = run.check(bad);
  EXPECT_EQ(c.code, 1);
  EXPECT_NE(c.err.find("objects[1] \"udi\": its code's quiet zone is marked by object \"sn\" at ("), std::string::npos)
      << c.err;
  const test::CliResult m = run.mark(bad);
  EXPECT_EQ(m.code, 1);
  EXPECT_TRUE(m.out.empty()) << m.out;
  EXPECT_NE(m.err.find("its code's quiet zone is marked by object \"sn\""), std::string::npos) << m.err;

  // Moved below the text: checked, marked, and the refused part consumed nothing (41 comes first).
  const std::string good = run.file("good.json", job_with(kCodeBelow));
  EXPECT_EQ(run.check(good).code, 0) << run.check(good).err;
  const test::CliResult g = run.mark(good);
  ASSERT_EQ(g.code, 0) << g.err;
  const auto part = nlohmann::json::parse(g.out);
  EXPECT_EQ(part["outcome"], "done");
  EXPECT_EQ(part["serials"]["serial"].get<std::int64_t>(), 41);
}

TEST(ObjectClearance, TwoTextsWhoseInksTouchAreRefusedTextsApartPass) {
  const Scratch run("marker_clearance_text");
  const test::CliResult over = run.check(run.file("over.json", job_with(kTextOver)));
  EXPECT_EQ(over.code, 1);
  EXPECT_NE(over.err.find("objects[0] \"sn\": its ink touches object \"lot\"'s at ("), std::string::npos) << over.err;
  EXPECT_NE(over.err.find("the spot is 40 µm); move the objects apart"), std::string::npos) << over.err;
  const test::CliResult apart = run.check(run.file("apart.json", job_with(kTextApart)));
  EXPECT_EQ(apart.code, 0) << apart.err;
}

}  // namespace
}  // namespace mark
