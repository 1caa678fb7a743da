// `marker mark --job` as a line runs it: job new → job check → mark three parts → log, the
// variables of --set, an abort (injected, and Ctrl-C on the real binary) recorded with its
// number void and the next run continuing after it, a failing device, a re-mark, and the
// options that belong to one mode only.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "driver/lmc/capture_link.hpp"
#include "marker/store/open_store.hpp"
#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

using test::run_cli;

std::vector<nlohmann::json> json_lines(const std::string& out) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

struct MarkJobCli : testing::Test {
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("marker-mark-job-" + std::to_string(::getpid()));
  std::string job = (dir / "bracket.json").string();
  std::string store;  // the station's, in the test's folder
  void SetUp() override {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    store = (test::use_station_state(dir) / "serials.sqlite").string();
    auto r = run_cli({"job", "new", "-o", job, "--text", "SN {serial} LOT {var:lot}",
                      "--width", "6", "--start", "41", "--height", "3", "--x", "-20",
                      "--power", "80", "--frequency", "40", "--var", "lot=A00"});
    ASSERT_EQ(r.code, 0) << r.err;
    // Audit row 1: the counter's creation (at the job's start, 41); parts are rows 2, 3, …
    r = run_cli({"serial", "create", "serial", "--job", job});
    ASSERT_EQ(r.code, 0) << r.err;
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  test::CliResult mark(const std::vector<std::string>& extra) { return test::run_mark_job(job, extra); }
  nlohmann::json serial() {
    return nlohmann::json::parse(run_cli({"serial", "show", "serial", "--job", job, "--json"}).out);
  }
  // The parts' rows (the counter's creation aside).
  std::vector<nlohmann::json> log() {
    std::vector<nlohmann::json> rows;
    for (auto& row : json_lines(run_cli({"log", "--json"}).out))
      if (row["kind"] != "create") rows.push_back(row);
    return rows;
  }
};

TEST_F(MarkJobCli, NewCheckMarkThreePartsAndLog) {
  auto r = run_cli({"job", "check", job, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto check = nlohmann::json::parse(r.out);
  EXPECT_EQ(check["objects"][0]["text"], "SN 000041 LOT A00");
  // job new --speed auto wrote the speed `mark --speed auto` picks for 3 mm text.
  const double speed = check["objects"][0]["pulse_spacing_um"].get<double>() * 40;
  EXPECT_GT(speed, 600);
  EXPECT_LE(speed, 1000);

  r = mark({"--count", "3", "--json", "--set", "lot=A17"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto parts = json_lines(r.out);
  ASSERT_EQ(parts.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const nlohmann::json& p = parts[i];
    EXPECT_EQ(p["part"], i + 1);
    EXPECT_EQ(p["text"], "SN 0000" + std::to_string(41 + i) + " LOT A17");
    EXPECT_EQ(p["serials"], nlohmann::json({{"serial", 41 + i}}));
    EXPECT_EQ(p["outcome"], "done");
    EXPECT_EQ(p["kind"], "mark");
    EXPECT_EQ(p["quality"]["class"], "high");
    EXPECT_FALSE(p["quality"]["separate_dots"].get<bool>());
    EXPECT_NEAR(p["pulse_spacing_um"].get<double>(), speed / 40, 0.02 * speed / 40);
    EXPECT_NEAR(p["pulse_overlap_fraction"].get<double>(), 1 - p["pulse_spacing_um"].get<double>() / 40, 1e-9);
    EXPECT_GT(p["mark_time_s"].get<double>(), 0.05);
    EXPECT_EQ(p["objects"][0]["device_figures"]["power_pct"], 80.0);
    EXPECT_EQ(p["objects"][0]["device_figures"]["frequency_khz"], 40.0);
    EXPECT_EQ(p["device"], "sim SL10");
  }
  const auto rows = log();
  ASSERT_EQ(rows.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(rows[i]["id"], parts[i]["mark_id"]);
    EXPECT_EQ(rows[i]["text"], parts[i]["text"]);
    EXPECT_EQ(rows[i]["serials"], parts[i]["serials"]);
    EXPECT_EQ(rows[i]["outcome"], "done");
    EXPECT_EQ(rows[i]["station"], "line-1");
    EXPECT_EQ(rows[i]["figures"]["pulse_spacing_um"], parts[i]["pulse_spacing_um"]);
    EXPECT_EQ(rows[i]["figures"]["quality"], parts[i]["quality"]);
  }
  EXPECT_EQ(serial()["next"], 44);
  EXPECT_EQ(serial()["highest_issued"], 43);

  // The text form: one line per part.
  r = mark({"--count", "2"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2);
  EXPECT_EQ(r.out.rfind("part 1/2  id 5  serial=44  \"SN 000044 LOT A00\"  done  ", 0), 0u) << r.out;
}

TEST_F(MarkJobCli, AnAbortIsRecordedVoidAndTheNextRunContinuesAfterIt) {
  auto r = mark({"--count", "3", "--json", "--inject", "abort@2000"});
  EXPECT_EQ(r.code, 130);
  auto parts = json_lines(r.out);
  ASSERT_EQ(parts.size(), 1u) << "no part after the aborted one";
  EXPECT_EQ(parts[0]["outcome"], "aborted");
  EXPECT_EQ(parts[0]["stopped_at"]["at"], 2000);
  EXPECT_EQ(parts[0]["objects"][0]["stopped_at"], 2000);
  EXPECT_NE(r.err.find("\nmarker: part 1 (id 2) aborted: object \"text\" (1 of 1) aborted at sample 2000: "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("laser off; its numbers are void (serial=41)"), std::string::npos) << r.err;
  EXPECT_EQ(serial()["next"], 42);

  r = mark({"--count", "2", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  parts = json_lines(r.out);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0]["serials"]["serial"], 42);
  EXPECT_EQ(parts[1]["serials"]["serial"], 43);
  const auto rows = log();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0]["outcome"], "aborted");
  EXPECT_EQ(rows[0]["serials"]["serial"], 41);
  EXPECT_NE(rows[0]["message"].get<std::string>().find("aborted at sample 2000"), std::string::npos);
}

TEST_F(MarkJobCli, AFailingDeviceIsRecordedFailed) {
  const auto r = mark({"--count", "2", "--json", "--inject", "fault@700"});
  EXPECT_EQ(r.code, 1);
  const auto parts = json_lines(r.out);
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0]["outcome"], "failed");
  EXPECT_EQ(parts[0]["objects"][0]["fault"]["category"], "device");
  EXPECT_EQ(parts[0]["objects"][0]["fault"]["at"], 700);
  EXPECT_NE(r.err.find("failed (device: simulated scanner (SL10): injected device fault at sample 700"),
            std::string::npos)
      << r.err;
  const auto rows = log();
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0]["outcome"], "failed");
  EXPECT_EQ(serial()["next"], 42);
}

// A job whose field is larger than its head's is refused before any serial is taken: not marked
// as if the 110 mm SL10 reached 300 mm, and not a part recorded failed with a serial used up.
TEST_F(MarkJobCli, AFieldLargerThanTheHeadsIsRefusedBeforeASerialIsTaken) {
  nlohmann::json j;
  std::ifstream(job) >> j;
  j["field_mm"] = 300;
  std::ofstream(job) << j.dump(2);
  const auto r = mark({"--count", "2"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("the job's field, 300 mm (--field, a job's field_mm), is larger than the 110 mm field of "
                       "device sim SL10; give at most 110"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(log().empty());
  EXPECT_EQ(serial()["next"], 41);
}

// A station's job names its board: `job new --device`, and `mark --job` marks every part on it
// (here the capture board, which writes the bytes instead of sending them): one list per part,
// each with that part's own serial.
TEST_F(MarkJobCli, TheJobsDeviceMarksEveryPart) {
  const std::string board = (dir / "line.lmc").string();
  const std::string on_board = (dir / "board.json").string();
  auto r = run_cli({"job", "new", "-o", on_board, "--text", "SN {serial}", "--start", "7",
                    "--height", "2", "--device", "lmc-capture:" + board});
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_cli({"mark", "--job", on_board, "--virtual-time", "--station", "line-1", "--count", "2",
               "--store", (dir / "board.sqlite").string(), "--create-counters", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto parts = json_lines(r.out);
  ASSERT_EQ(parts.size(), 2u);
  for (const auto& p : parts) {
    EXPECT_EQ(p["outcome"], "done");
    EXPECT_EQ(p["device"], "lmc 00000000");
    EXPECT_EQ(p["objects"][0]["device_figures"]["packets"], 1.0);
  }
  EXPECT_EQ(parts[0]["objects"][0]["text"], "SN 7");
  EXPECT_EQ(parts[1]["objects"][0]["text"], "SN 8");
  // The board is opened once per run: the capture holds both parts' lists, one packet each.
  std::size_t lists = 0;
  for (const auto& rec : lmc::read_capture(board)) lists += rec.packet;
  EXPECT_EQ(lists, 2u);
  r = run_cli({"job", "new", "-o", (dir / "bad.json").string(), "--text", "SN {serial}",
               "--device", "lmc:xyz"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("device: 'lmc:xyz': a board serial is 1 to 8 hex digits"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.json"));
}

TEST_F(MarkJobCli, SetVariablesAndTheirRefusals) {
  auto r = mark({"--json", "--set", "lot=B-9"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json_lines(r.out)[0]["text"], "SN 000041 LOT B-9");
  r = mark({"--set", "lott=B9"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: --set lott=…: no template of " + job + " uses {var:lott}\n");
  r = mark({"--set", "B9"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: --set 'B9': expected NAME=VALUE, e.g. --set lot=A17\n");
  // A variable without a default must be set.
  ASSERT_EQ(run_cli({"job", "new", "-o", job, "--force", "--text", "LOT {var:lot}", "--x", "-20"}).code, 0);
  r = mark({});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: " + job + ": {var:lot} has no default in the job: give --set lot=VALUE\n");
  EXPECT_EQ(log().size(), 1u) << "the refused runs consumed nothing";
}

TEST_F(MarkJobCli, ARemarkLinksTheRowAndTakesNoNumber) {
  ASSERT_EQ(mark({"--count", "2"}).code, 0);
  auto r = mark({"--remark", "2", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto part = json_lines(r.out).at(0);
  EXPECT_EQ(part["kind"], "remark");
  EXPECT_EQ(part["remark_of"], 2);
  EXPECT_EQ(part["serials"]["serial"], 41);
  EXPECT_EQ(part["text"], "SN 000041 LOT A00");
  EXPECT_EQ(serial()["next"], 43);
  const auto rows = log();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[2]["kind"], "remark");
  EXPECT_EQ(rows[2]["remark_of"], 2);
  EXPECT_EQ(rows[2]["outcome"], "done");
  r = mark({"--remark", "2", "--count", "2"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--count and --set do not apply"), std::string::npos) << r.err;
}

// A re-mark after the job file was edited (power 80 → 50): refused, naming the option; with
// --allow-changed-job marked with the edited job, its row carrying the new job's hash and a note
// naming the version the part was first marked with. No number is consumed either way.
TEST_F(MarkJobCli, ARemarkWithAnEditedJobNeedsAllowChangedJobAndIsNoted) {
  ASSERT_EQ(mark({}).code, 0);
  const std::string first_hash = log().at(0)["job_sha256"];
  std::ifstream in(job);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const std::size_t at = text.find("\"power_pct\": 80");
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, 17, "\"power_pct\": 50");
  std::ofstream(job) << text;
  auto r = mark({"--remark", "2"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("not with this job file (to re-mark it with this one: --allow-changed-job"), std::string::npos)
      << r.err;
  EXPECT_EQ(mark({"--allow-changed-job"}).code, 1) << "only a re-mark reads it";
  r = mark({"--remark", "2", "--allow-changed-job", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json_lines(r.out).at(0)["text"], "SN 000041 LOT A00");
  const auto rows = log();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1]["kind"], "remark");
  EXPECT_EQ(rows[1]["outcome"], "done");
  EXPECT_NE(rows[1]["job_sha256"], first_hash);
  EXPECT_EQ(rows[1]["note"], "job changed since the part was marked with " + job + " (SHA-256 " +
                                 first_hash.substr(0, 12) + "…)");
  EXPECT_EQ(serial()["next"], 42);
}

TEST_F(MarkJobCli, OptionsOfTheOtherModeAreRefused) {
  auto r = mark({"--speed", "500"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: --speed does not apply with --job: the job file sets it (see marker job check)\n");
  r = run_cli({"mark", "ABC", "--job", job});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: a text to mark does not apply with --job: the job file sets it (see marker job check)\n");
  r = run_cli({"mark", "ABC", "--count", "3", "--virtual-time"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: --count applies to a production run: give --job FILE\n");
  r = run_cli({"mark"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: mark: give the text to mark (or --code), or --job FILE\n");
  r = mark({"--count", "0"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: --count: 0 is outside the range 1 to 1000000000\n");
  EXPECT_TRUE(log().empty()) << "nothing refused may mark";
}

TEST_F(MarkJobCli, CtrlCFinishesThePartAbortedAndStartsNoOther) {
  // The real binary in real time, parts of several seconds (50 mm/s); SIGINT once the first
  // part's number is committed (its audit row exists), so the signal lands while it marks.
  ASSERT_EQ(run_cli({"job", "new", "-o", job, "--force", "--text", "SN {serial}", "--width", "6",
                     "--start", "41", "--height", "3", "--x", "-20", "--speed", "50"})
                .code,
            0);
  const std::string binary = std::string(MARKER_BINARY_DIR) + "/marker/marker";
  const auto out = dir / "run.jsonl", err = dir / "run.err";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (!freopen(out.c_str(), "w", stdout) || !freopen(err.c_str(), "w", stderr)) _exit(99);
    execl(binary.c_str(), binary.c_str(), "mark", "--job", job.c_str(), "--count", "3", "--json",
          "--station", "line-1", static_cast<char*>(nullptr));
    _exit(98);
  }
  const auto t0 = std::chrono::steady_clock::now();
  for (;;) {
    ASSERT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(60)) << "no part started";
    if (std::filesystem::exists(store)) {
      try {
        bool marking = false;
        for (const AuditRow& row : open_store(store, StoreAccess::read_only)->log())
          marking = marking || row.mark.kind == AuditKind::mark;
        if (marking) break;
      } catch (const std::exception&) {
        // the child is still creating the store
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of finishing the part";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  const auto parts = json_lines(text.str());
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0]["outcome"], "aborted");
  EXPECT_GT(parts[0]["stopped_at"]["at"].get<int>(), 0);
  EXPECT_LE(parts[0]["objects"][0]["stop_latency_samples"].get<int>(), 100);
  EXPECT_LT(parts[0]["objects"][0]["ink_marked_fraction"].get<double>(), 1.0);
  std::ifstream e(err);
  std::stringstream said;
  said << e.rdbuf();
  EXPECT_NE(said.str().find("\nmarker: part 1 (id 2) interrupted: object \"text\" (1 of 1) aborted at sample "), std::string::npos)
      << said.str();
  const auto rows = log();
  ASSERT_EQ(rows.size(), 1u) << "no further part started";
  EXPECT_EQ(rows[0]["outcome"], "aborted");
  // The next run continues after the void number.
  ASSERT_EQ(run_cli({"job", "new", "-o", job, "--force", "--text", "SN {serial}", "--width", "6",
                     "--start", "41", "--height", "3", "--x", "-20"})
                .code,
            0);
  const auto r = mark({"--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json_lines(r.out)[0]["serials"]["serial"], 42);
}

// A job with a text and a UDI code carrying the same serial: every part's code is read back off
// the simulated mark with that part's number, the serials consecutive.
TEST_F(MarkJobCli, EachPartsCodeReadsBackWithItsOwnSerial) {
  {
    std::ofstream f(job);
    f << R"({
  "format": "marker-job/1",
  "head": {"model": "SL10", "spot_diameter_um": 40},
  "counters": {"serial": {"start": 7, "width": 6}},
  "pens": {"text": {"speed_mm_s": 800}, "code": {"speed_mm_s": 1000}},
  "objects": [
    {"name": "sn", "pen": "text", "template": "SN {serial}", "height_mm": 2, "x_mm": -14, "y_mm": 0},
    {"name": "udi", "kind": "code", "pen": "code", "symbology": "gs1-datamatrix",
     "template": "(01)09506000134352(21){serial}", "module_mm": 0.3, "x_mm": 8, "y_mm": 0}
  ]
})";
  }
  // A store of its own, where the job's counter starts at its start, 7.
  const auto r = mark({"--count", "2", "--json", "--store", (dir / "codes.sqlite").string(), "--create-counters"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto parts = json_lines(r.out);
  ASSERT_EQ(parts.size(), 2u);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string serial = i == 0 ? "000007" : "000008";
    EXPECT_EQ(parts[i]["serials"]["serial"], 7 + static_cast<int>(i));
    EXPECT_EQ(parts[i]["objects"][0]["text"], "SN " + serial);
    const nlohmann::json& codes = parts[i]["objects"][1]["codes"];
    ASSERT_EQ(codes.size(), 1u) << parts[i].dump();
    EXPECT_EQ(codes[0]["symbology"], "gs1-datamatrix");
    EXPECT_TRUE(codes[0]["data_match"].get<bool>()) << codes[0].dump();
    EXPECT_TRUE(codes[0]["decoded"].get<bool>());
    EXPECT_NE(codes[0]["decoded_data"].get<std::string>().find(serial), std::string::npos) << codes[0].dump();
  }
}

}  // namespace
}  // namespace mark
