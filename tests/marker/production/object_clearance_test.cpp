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

// A frame laid over a text on purpose: "overlaps" on either object lets their inks touch, and
// the part marks; it never opens a code's quiet zone, and a wrong name is refused where it is.
TEST(ObjectClearance, ObjectsLaidOverEachOtherOnPurposeSayWhichAndMark) {
  const Scratch run("marker_clearance_overlay");
  const std::string over = std::string(kTextOver).insert(1, R"("overlaps": ["sn"], )");
  const test::CliResult named_later = run.check(run.file("named_later.json", job_with(over)));
  EXPECT_EQ(named_later.code, 0) << named_later.err;
  // Said on the first object, naming one further down the list: the same.
  std::string first_names = job_with(kTextOver);
  first_names.insert(first_names.find(R"("name": "sn")"), R"("overlaps": ["lot"], )");
  const std::string both = run.file("first_names.json", first_names);
  EXPECT_EQ(run.check(both).code, 0) << run.check(both).err;
  const test::CliResult m = run.mark(both);
  ASSERT_EQ(m.code, 0) << m.err;
  EXPECT_EQ(nlohmann::json::parse(m.out)["outcome"], "done");

  const auto refused = [&](const std::string& name, const std::string& second, const std::string& expected) {
    const test::CliResult c = run.check(run.file(name, job_with(second)));
    EXPECT_EQ(c.code, 1) << name;
    EXPECT_NE(c.err.find(expected), std::string::npos) << name << ": " << c.err;
    EXPECT_EQ(c.err.find('\n'), c.err.size() - 1) << name << ": one line: " << c.err;
  };
  refused("code.json", std::string(kCodeOnTheText).insert(1, R"("overlaps": ["sn"], )"),
          "objects[1].overlaps[0]: \"udi\" is a code: its quiet zone must stay bare, so no object may lie over it");
  refused("unknown.json", std::string(kTextOver).insert(1, R"("overlaps": ["sm"], )"),
          "objects[1].overlaps[0]: no object named \"sm\"");
  refused("self.json", std::string(kTextOver).insert(1, R"("overlaps": ["lot"], )"),
          "objects[1].overlaps[0]: \"lot\" is this object");
  refused("twice.json", std::string(kTextOver).insert(1, R"("overlaps": ["sn", "sn"], )"),
          "objects[1].overlaps[1]: \"sn\" is named twice");
  refused("newline.json", std::string(kTextOver).insert(1, R"("overlaps": ["s\nn"], )"),
          "objects[1].overlaps[0]: a object name cannot hold control characters");
  refused("notalist.json", std::string(kTextOver).insert(1, R"("overlaps": "sn", )"),
          "objects[1].overlaps: expected a list of object names");
}

}  // namespace
}  // namespace mark
