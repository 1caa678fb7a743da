// `marker gcode` as a milling machine sees it, end to end through the command line and LinuxCNC's
// rs274: the stock and the travel instead of the galvo field (with refusals that name the side
// and the distance), F-Engrave's spacing options, the warning for a tool as wide as a gap,
// programs of 1 to 160 rows in mm and inch, V-carving from the command line, and QCAD's
// normal.cxf cut without a lift where its strokes meet at 1 mm and at 100 mm, every cut on the
// strokes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "../cli_runner.hpp"
#include "cnc_checks.hpp"
#include "cnc_files.hpp"
#include "marker/cli/layout_options.hpp"

namespace mark::test {
namespace {

namespace fs = std::filesystem;

const std::string kNormalCxf = std::string(MARKER_SOURCE_DIR) + "/tests/fonts/data/normal.cxf";
const std::string kDejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const std::string kSentence = "The quick brown fox jumps over the lazy dog. 0123456789 ABCDEF";  // 62 characters

std::string machine_out_path(const std::string& name) { return cnc_out_path("cnc_machine", name); }

std::string rows(int n) {
  std::string t;
  for (int k = 0; k < n; ++k) t += (k ? "\\n" : "") + kSentence;
  return t;
}

nlohmann::json gcode_json(std::vector<std::string> args, CliResult* result = nullptr) {
  args.insert(args.begin(), "gcode");
  args.push_back("--json");
  const CliResult r = run_cli(args);
  if (result) *result = r;
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

// Refused with exit 1, the last line on stderr holding every fragment (warnings may come
// before it), and no file.
void expect_refused(std::vector<std::string> args, const std::vector<std::string>& fragments, const std::string& file) {
  args.insert(args.begin(), "gcode");
  const CliResult r = run_cli(args);
  EXPECT_EQ(r.code, 1) << r.out;
  const std::string last = r.err.substr(r.err.rfind("marker: "));
  EXPECT_EQ(last.rfind("marker: warning", 0), std::string::npos) << r.err;
  for (const std::string& f : fragments) EXPECT_NE(last.find(f), std::string::npos) << r.err << "\n  expected: " << f;
  EXPECT_EQ(std::count(last.begin(), last.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(file));
}

TEST(GcodeMachine, StockAndTravelReplaceTheGalvoField) {
  const std::string file = machine_out_path("stock.ngc");
  // 40 rows at 1 mm and a 100 mm base point: far outside a 110 mm galvo field, fine on a mill.
  const nlohmann::json j = gcode_json({rows(40), "--font", kNormalCxf, "--height", "1", "--x", "100", "--y", "100",
                                       "--tool-diameter", "0.2", "--stock", "160,110", "--travel", "300,200", "-o", file});
  const auto& c = j["cut_bounds_mm"];
  EXPECT_NEAR(c["x_min"].get<double>(), 100 - 0.1, 1e-9);  // the tool's radius left of the first letter
  EXPECT_NEAR(c["y_max"].get<double>(), 101 + 0.1, 1e-6);  // cap height 1 mm above the first baseline
  EXPECT_EQ(j["stock_mm"]["x_max"].get<double>(), 160);
  EXPECT_EQ(j["travel_mm"]["x"].get<double>(), 300);
  // The same job on a stock too narrow and too low, its corner moved: refused, naming each side.
  const std::string refused = machine_out_path("refused.ngc");
  expect_refused({rows(40), "--font", kNormalCxf, "--height", "1", "--x", "100", "--y", "100", "--tool-diameter",
                  "0.2", "--stock", "0,40,145,60", "-o", refused},
                 {"the cuts leave the stock at the right by ", "at the top by ", "--stock is x 0.000 to 145.000 mm"},
                 refused);
  // A travel too short in x for the program.
  expect_refused({rows(2), "--font", kNormalCxf, "--height", "5", "--travel", "100,100", "-o", refused},
                 {"the program spans ", "mm more in x than the --travel 100.000 x 100.000 mm allows"}, refused);
  // The base point lies within the travel.
  expect_refused({"AB", "--x", "500", "--travel", "300,200", "-o", refused},
                 {"--x: 500 is outside the range -300 to 300 mm (within the --travel, 300 x 200 mm)"}, refused);
  expect_refused({"AB", "--stock", "10", "-o", refused}, {"--stock '10': expected W,H or X,Y,W,H"}, refused);
  expect_refused({"AB", "--field", "200", "-o", refused}, {"--field"}, refused);
}

TEST(GcodeMachine, InchProgramsSayG20AndCutTheSameStrokes) {
  const std::string mm = machine_out_path("units_mm.ngc"), in = machine_out_path("units_in.ngc");
  const nlohmann::json a = gcode_json({"SN 42", "--height", "4", "--units", "mm", "-o", mm});
  const nlohmann::json b = gcode_json({"SN 42", "--height", "4", "--units", "in", "-o", in});
  EXPECT_NE(slurp(mm).find("G21"), std::string::npos);
  EXPECT_NE(slurp(in).find("G20"), std::string::npos);
  EXPECT_EQ(b["units"], "inch");
  const Rs274Run rm = run_rs274(slurp(mm), "units_mm"), ri = run_rs274(slurp(in), "units_in");
  ASSERT_EQ(rm.exit_code, 0) << rm.errors;
  ASSERT_EQ(ri.exit_code, 0) << ri.errors;
  ASSERT_EQ(rm.moves.size(), ri.moves.size());
  for (std::size_t k = 0; k < rm.moves.size(); ++k)
    EXPECT_LE((rm.moves[k].end - ri.moves[k].end).norm(), 0.0026) << k;  // 5 decimals of inch, printed as 4
}

TEST(GcodeMachine, FEngraveSpacingInPercentOfTheHeight) {
  const std::string file = machine_out_path("spacing.ngc");
  // Two 'I's of the built-in font at 10 mm: the second starts at the first's right edge plus the
  // character spacing; a space between words is the word spacing.
  const nlohmann::json tight = gcode_json({"II", "--height", "10", "--char-spacing", "0", "-o", file});
  const nlohmann::json loose = gcode_json({"II", "--height", "10", "--char-spacing", "50", "-o", file});
  const double w_tight = tight["cut_bounds_mm"]["x_max"].get<double>() - tight["cut_bounds_mm"]["x_min"].get<double>();
  const double w_loose = loose["cut_bounds_mm"]["x_max"].get<double>() - loose["cut_bounds_mm"]["x_min"].get<double>();
  EXPECT_NEAR(w_loose - w_tight, 5.0, 1e-6);  // 50 % of 10 mm more between the two letters
  const nlohmann::json words = gcode_json({"I I", "--height", "10", "--char-spacing", "0", "--word-spacing", "100", "-o", file});
  const double w_words = words["cut_bounds_mm"]["x_max"].get<double>() - words["cut_bounds_mm"]["x_min"].get<double>();
  EXPECT_NEAR(w_words - w_tight, 10.0, 1e-6);  // a 10 mm space
  CliResult r;
  r = run_cli({"gcode", "II", "--char-spacing", "-60", "-o", file});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--char-spacing: -60 is outside the range -50 to 1000 % of the character height"), std::string::npos)
      << r.err;
}

TEST(GcodeMachine, WarnsWhenTheToolIsAsWideAsAGap) {
  const std::string file = machine_out_path("gap.ngc");
  CliResult r;
  // 1 mm tool on 1 mm text: the grooves of neighbouring strokes run into one.
  const nlohmann::json wide = gcode_json({"HELLO", "--height", "1", "--tool-diameter", "1", "-o", file}, &r);
  ASSERT_FALSE(wide["narrowest_gap_mm"].is_null());
  EXPECT_LT(wide["narrowest_gap_mm"].get<double>(), 1.0);
  EXPECT_NE(r.err.find("marker: warning: the tool (1 mm) is at least as wide as the narrowest gap between strokes"),
            std::string::npos)
      << r.err;
  // A fine tool on the same text: no warning.
  const nlohmann::json fine = gcode_json({"HELLO", "--height", "1", "--tool-diameter", "0.05", "-o", file}, &r);
  EXPECT_TRUE(fine["narrowest_gap_mm"].is_null());
  EXPECT_TRUE(fine["warnings"].empty()) << fine["warnings"];
}

// rs274 runs every program: plain (depression) of 1 to 160 rows in mm and inch, and the strokes
// of the 160 rows are cut where they are.
TEST(GcodeMachine, Rs274RunsOneTo160RowsInMmAndInch) {
  for (int n : {1, 10, 160})
    for (const char* units : {"mm", "in"}) {
      const std::string name = "rows_" + std::to_string(n) + "_" + units;
      const std::string file = machine_out_path(name + ".ngc");
      const nlohmann::json j = gcode_json({rows(n), "--font", kNormalCxf, "--height", "1", "--tool-diameter", "0.1",
                                           "--depth", "0.1", "--units", units, "-o", file});
      const Rs274Run run = run_rs274(slurp(file), name);
      ASSERT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;
      if (n == 160 && std::string(units) == "mm") {
        cli::LayoutArgs l;
        l.font = kNormalCxf;
        l.height_mm = 1;
        CutSettings s;
        s.tool_diameter_mm = 0.1;
        s.depth_mm = 0.1;
        check_depression(cli::lay_out_text(rows(n), l, cli::to_layout_options(l, Range{-1e4, 1e4, "mm"})).figure, run, s,
                         0.0001);
      }
    }
}

// QCAD's normal.cxf misses its own joins by up to 2.7e-5 of the height: at 1 mm and at 100 mm the
// cutter lifts as often (the joins hold at every height), never re-plunges where it just lifted,
// and every cut lies on the strokes.
TEST(GcodeMachine, NoLiftWhereStrokesMeetAtAnyHeight) {
  std::size_t retracts_1mm = 0;
  for (double h : {1.0, 100.0}) {
    const std::string name = "joins_" + std::to_string(static_cast<int>(h));
    const std::string file = machine_out_path(name + ".ngc");
    const nlohmann::json j = gcode_json({kSentence, "--font", kNormalCxf, "--height", std::to_string(h), "--tool-diameter",
                                         "0.1", "--depth", "0.1", "-o", file});
    if (h == 1.0) retracts_1mm = j["retracts"].get<std::size_t>();
    EXPECT_EQ(j["retracts"].get<std::size_t>(), retracts_1mm) << h << " mm";
    const Rs274Run run = run_rs274(slurp(file), name);
    ASSERT_EQ(run.exit_code, 0) << run.errors;
    // A retract and the next plunge never at the same spot (within the join tolerance).
    Eigen::Vector3d lifted_at(1e9, 1e9, 0);
    for (const CanonMove& m : run.moves) {
      if (m.kind == CanonMove::traverse && m.start.z() < 0 && m.end.z() > m.start.z()) lifted_at = m.start;
      if (m.kind == CanonMove::feed && m.start.z() >= 0 && m.end.z() < 0) {
        EXPECT_GT((m.end.head<2>() - lifted_at.head<2>()).norm(), 1e-4 * h) << "re-plunged where it lifted";
      }
    }
    cli::LayoutArgs l;
    l.font = kNormalCxf;
    l.height_mm = h;
    CutSettings s;
    s.tool_diameter_mm = 0.1;
    s.depth_mm = 0.1;
    check_depression(cli::lay_out_text(kSentence, l, cli::to_layout_options(l, Range{-1e4, 1e4, "mm"})).figure, run, s,
                     0.0001);
  }
  EXPECT_GT(retracts_1mm, 50u);
}

TEST(GcodeMachine, VCarveFromTheCommandLineInMmAndInch) {
  for (const char* units : {"mm", "in"}) {
    const std::string name = std::string("vcarve_cli_") + units;
    const std::string file = machine_out_path(name + ".ngc"), cleanup = machine_out_path(name + "_cleanup.ngc");
    const std::string preview = machine_out_path(name + ".svg");
    CliResult r;
    const nlohmann::json j = gcode_json({"Bo", "--font", kDejaVu, "--height", "20", "--mode", "v-carve", "--bit-angle",
                                         "60", "--tool-diameter", "6", "--max-depth", "0.8", "--flat-bottom", "1",
                                         "--cleanup-output", cleanup, "--units", units, "--preview", preview, "-o", file},
                                        &r);
    EXPECT_NEAR(j["vcarve"]["deepest_mm"].get<double>(), 0.8, 1e-9);
    EXPECT_GT(j["vcarve"]["flat_area_mm2"].get<double>(), 100);
    EXPECT_GT(j["vcarve"]["cleanup_lines"].get<std::size_t>(), 100u);
    for (const std::string& f : {file, cleanup}) {
      const Rs274Run run = run_rs274(slurp(f), fs::path(f).stem().string());
      ASSERT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;
    }
    EXPECT_NE(slurp(preview).find("<svg"), std::string::npos);
  }
  const std::string file = machine_out_path("vcarve_refused.ngc");
  expect_refused({"AB", "--bit-angle", "60", "-o", file}, {"--bit-angle applies to --mode v-carve only"}, file);
  expect_refused({"AB", "--mode", "v-carve", "--font", kDejaVu, "--flat-bottom", "1", "-o", file},
                 {"--flat-bottom needs --cleanup-output FILE.ngc"}, file);
  expect_refused({"AB", "--mode", "v-carve", "-o", file}, {"v-carve: 'A' (U+0041) has an open stroke"}, file);
}

TEST(GcodeMachine, ProtrusionRunsInMmAndInch) {
  for (const char* units : {"mm", "in"}) {
    const std::string name = std::string("protrusion_") + units;
    const std::string file = machine_out_path(name + ".ngc");
    gcode_json({"OK 7", "--height", "4", "--mode", "protrusion", "--tool-diameter", "0.5", "--gap", "1", "--units", units,
                "-o", file});
    const Rs274Run run = run_rs274(slurp(file), name);
    ASSERT_EQ(run.exit_code, 0) << run.errors;
  }
}

}  // namespace
}  // namespace mark::test
