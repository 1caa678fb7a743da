// Bad input on every command: each refusal is exactly one line on stderr naming the option, the
// value and the allowed range (or the file and the system's reason), exit status 1, and no file
// left behind — not the output, not a temporary. And every numeric option of every command has a
// registered range, so a new option without one fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/option_ranges.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

// A folder of the running test's own (CTest runs the tests of this file in parallel processes).
fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / "marker_cli_refusal_test" /
                     testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(d);
  return d;
}

struct Refusal {
  std::vector<std::string> args;
  std::string message;  // the whole line, without "marker: " and the newline
};

// Runs each case with its output files in a fresh folder and checks the folder stays empty.
void expect_refusals(const std::vector<Refusal>& cases) {
  for (const Refusal& c : cases) {
    const fs::path dir = temp_dir() / "out";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::vector<std::string> args;
    for (const std::string& a : c.args) args.push_back(a.rfind("OUT/", 0) == 0 ? (dir / a.substr(4)).string() : a);
    const test::CliResult r = test::run_cli(args);
    std::string shown;
    for (const std::string& a : c.args) shown += a + " ";
    EXPECT_EQ(r.code, 1) << shown;
    EXPECT_EQ(r.err, "marker: " + c.message + "\n") << shown;
    EXPECT_TRUE(fs::is_empty(dir)) << shown << ": left " << fs::directory_iterator(dir)->path();
  }
}

TEST(CliRefusal, LayoutOptionsOutsideTheirRanges) {
  expect_refusals({
      {{"layout", "X", "--angle", "1e300"}, "--angle: 1e300 is outside the range -360 to 360 degrees"},
      {{"mark", "X", "--angle", "1e20"}, "--angle: 1e20 is outside the range -360 to 360 degrees"},
      {{"layout", "X", "--height", "1e308"}, "--height: 1e308 is outside the range 0.01 to 10000 mm"},
      {{"layout", "X", "--height", "nan"}, "--height: nan is outside the range 0.01 to 10000 mm"},
      {{"layout", "X", "--height", "five"}, "--height: 'five' is not a number (range: 0.01 to 10000 mm)"},
      {{"layout", "X", "--width-factor", "0"}, "--width-factor: 0 is outside the range 0.05 to 20"},
      {{"layout", "X", "--line-spacing", "0.1"}, "--line-spacing: 0.1 is outside the range 0.5 to 20"},
      {{"layout", "X", "--italic", "80"}, "--italic: 80 is outside the range -75 to 75 degrees"},
      {{"layout", "X", "--field", "0"}, "--field: 0 is outside the range 1 to 10000 mm"},
      {{"layout", "X", "--x", "60"}, "--x: 60 is outside the range -55 to 55 mm (the --field is 110 mm)"},
      {{"layout", "X", "--y", "-30", "--field", "50"}, "--y: -30 is outside the range -25 to 25 mm (the --field is 50 mm)"},
      // The simulated SL10 is a 110 mm head: a larger field is refused, not marked as if it reached.
      {{"mark", "X", "--field", "300"},
       "the job's field, 300 mm (--field, a job's field_mm), is larger than the 110 mm field of device sim SL10; give at most 110"},
      {{"code", "datamatrix", "X", "--field", "110.5"},
       "the job's field, 110.5 mm (--field, a job's field_mm), is larger than the 110 mm field of device sim SL10; give at most 110"},
      {{"layout", "X", "--circle", "0,0,1e300"},
       "--circle '0,0,1e300' radius: 1e+300 is outside the range above 0, up to 10000 mm"},
      {{"layout", "X", "--circle", "0,inf,10"},
       "--circle '0,inf,10' centre y: inf is outside the range -10000 to 10000 mm"},
      {{"layout", "X", "--circle", "0,0,10,4"}, "--circle '0,0,10,4': expected CX,CY,R in millimetres"},
      {{"layout", "X", "--circle", "0,zero,10"}, "--circle '0,zero,10': 'zero' is not a number"},
      {{"layout", "X", "--circle", "0,0,10", "--start-angle", "400"},
       "--start-angle: 400 is outside the range -360 to 360 degrees"},
      {{"layout", "AIA", "--gap", "-3"},
       "letter gap -3 mm makes the letter after 'I' (advance 1.500 mm) step backwards; the gap must be "
       "more than -1.500 mm for this text"},
      {{"layout", "ABCDEFGHIJKLMNOPQRSTUVWXYZ"},
       "the text layout leaves the field by 48.250 mm at the right: it spans x 0.500 to 103.250 mm, y 0.000 "
       "to 5.000 mm; the field is 110.000 mm square (±55.000 mm); lower --height, move the text with --x, --y "
       "or --align, or enlarge --field"},
      {{"layout", "X", "--bogus"}, "layout: unknown option --bogus"},
      {{"layout"}, "text is required"},
  });
}

TEST(CliRefusal, OutputPathsAreCheckedBeforeAnyWork) {
  expect_refusals({
      {{"preview", "X", "-o", "/nonexistent-dir/x.png"},
       "--output '/nonexistent-dir/x.png': directory '/nonexistent-dir': No such file or directory"},
      {{"preview", "X", "-o", "/proc/x.png"}, "--output '/proc/x.png': cannot create a file in '/proc': No such file or directory"},
      {{"preview", "X", "-o", "/etc/hostname/x.svg"}, "--output '/etc/hostname/x.svg': '/etc/hostname' is not a directory"},
      {{"preview", "X", "-o", "OUT/x.jpg"}, "--output '" + (temp_dir() / "out/x.jpg").string() + "': the name must end in .svg or .png"},
      {{"gcode", "X", "-o", "/nonexistent-dir/a.ngc"},
       "--output '/nonexistent-dir/a.ngc': directory '/nonexistent-dir': No such file or directory"},
      // The program is not written when the preview cannot be.
      {{"gcode", "X", "-o", "OUT/a.ngc", "--preview", "/nonexistent-dir/a.svg"},
       "--preview '/nonexistent-dir/a.svg': directory '/nonexistent-dir': No such file or directory"},
      {{"peen", "X", "-o", "OUT/a.ngc", "--preview", "OUT/a.pdf"},
       "--preview '" + (temp_dir() / "out/a.pdf").string() + "': the name must end in .svg or .png"},
      {{"peen", "X", "-o", "OUT/a.txt"},
       "--output '" + (temp_dir() / "out/a.txt").string() + "': the name must end in .csv, .ngc, .nc or .gcode"},
  });
  // A directory given as the file.
  const test::CliResult r = test::run_cli({"gcode", "X", "-o", temp_dir().string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: --output '" + temp_dir().string() + "': is a directory\n");
}

TEST(CliRefusal, GcodeAndToolMeasureOptions) {
  expect_refusals({
      {{"gcode", "X", "-o", "OUT/a.ngc", "--tool-diameter", "1e300"},
       "--tool-diameter: 1e300 is outside the range 0.01 to 50 mm"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--depth", "0"}, "--depth: 0 is outside the range 0.001 to 50 mm"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--feed", "1e-300"}, "--feed: 1e-300 is outside the range 1 to 100000 mm/min"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--spindle", "-5"}, "--spindle: -5 is outside the range 0, or 1 to 200000 rpm"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--safe-z", "1e300"}, "--safe-z: 1e300 is outside the range 0.1 to 1000 mm"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--arc-tolerance", "1e-300"},
       "--arc-tolerance: 1e-300 is outside the range 0.001 to 1 mm"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--mode", "protrusion", "--stepover", "1e-6"},
       "--stepover: 1e-6 is outside the range 0, or 0.001 to 25 mm"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--mode", "protrusion", "--stepover", "0.6"},
       "--stepover: 0.6 is outside the range 0.05 to 0.5 mm (from 5 % of the --tool-diameter to its radius)"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--mode", "protrusion", "--margin", "1e300"},
       "--margin: 1e300 is outside the range 0, or 0.01 to 1000 mm"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--mode", "protrusion", "--stroke-width", "1e300"},
       "--stroke-width: 1e300 is outside the range 0, or 0.01 to 100 mm"},
      // X grown by half the 1 mm stroke is 4 × 6 mm; with 1000 mm margins and inset by the tool
      // radius the plate is 2003 × 2005 mm: 1001.5 mm from wall to middle, 20030 loops of 0.05 mm.
      {{"gcode", "X", "-o", "OUT/a.ngc", "--mode", "protrusion", "--margin", "1000", "--stepover", "0.05"},
       "the pocket around the letters needs up to 20030 nested loops at a step-over of 0.05 mm, more than 1000; "
       "raise the step-over or narrow the margin"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--dialect", "plain", "--header", std::string(80, 'G')},
       "header line 'GGGGGGGGGGGGGGGGGGGG…' has 80 characters, more than the plain dialect's 79 per line"},
      {{"gcode", "X", "-o", "OUT/a.ngc", "--mode", "bogus"}, "--mode: 'bogus' is not one of depression, protrusion, v-carve"},
      {{"tool-measure", "x.png", "--pixel-size", "0"}, "--pixel-size: 0 is outside the range 0.01 to 10000 µm"},
      {{"tool-measure", "x.png", "--pixel-size", "5", "--tangential-angle", "0"},
       "--tangential-angle: 0 is outside the range above 0, up to 90 degrees"},
      {{"tool-measure", "x.png", "--pixel-size", "5", "--nominal-diameter", "-1"},
       "--nominal-diameter: -1 is outside the range 0.001 to 1000 mm"},
  });
}

TEST(CliRefusal, PeenPlansThatWouldBeNonsenseOrTooLarge) {
  expect_refusals({
      {{"peen", "X", "--height", "1e308"}, "--height: 1e308 is outside the range 0.01 to 10000 mm"},
      {{"peen", "VIN 1", "--font", "builtin", "--pitch", "1e-5"},
       "--pitch: 1e-05 is outside the range 0.1 to 5 mm (from 4 motor steps at --steps-per-mm 40 up to the "
       "--height)"},
      {{"peen", "VIN 1", "--font", "builtin", "--pitch", "0.001"},
       "--pitch: 0.001 is outside the range 0.1 to 5 mm (from 4 motor steps at --steps-per-mm 40 up to the "
       "--height)"},
      {{"peen", "X", "--steps-per-mm", "0.001"}, "--steps-per-mm: 0.001 is outside the range 1 to 10000 steps/mm"},
      {{"peen", "X", "--steps-per-mm", "1"},
       "--height 5: the 5x7 dots would be 0.833333 mm apart, closer than 4 mm (4 motor steps at --steps-per-mm "
       "1); raise --height or --steps-per-mm"},
      {{"peen", "X", "--height", "0.3"},
       "--height 0.3: the 5x7 dots would be 0.05 mm apart, closer than 0.1 mm (4 motor steps at --steps-per-mm "
       "40); raise --height or --steps-per-mm"},
      {{"peen", "X", "--speed", "1e-300"}, "--speed: 1e-300 is outside the range 1 to 5000 mm/s"},
      {{"peen", "X", "--accel", "1e-10"}, "--accel: 1e-10 is outside the range 10 to 100000 mm/s²"},
      {{"peen", "X", "--strike-ms", "1e300"}, "--strike-ms: 1e300 is outside the range 0 to 1000 ms"},
      {{"peen", "X", "--window", "1e300x5"},
       "--window '1e300x5' width: 1e+300 is outside the range above 0, up to 110 mm (the --field is 110 mm)"},
      {{"peen", "X", "--window", "60"}, "--window '60': expected WIDTHxHEIGHT in millimetres, e.g. 63x38"},
      {{"peen", "X", "--pitch", "1"}, "--pitch: the 5x7 dot font's pitch follows --height"},
      {{"peen", "M\\nM\\nM\\nM\\nM\\nM\\nM", "--font", "builtin", "--height", "14", "--field", "2000",
        "--steps-per-mm", "1000", "--pitch", "0.004"},
       "--pitch 0.004 mm gives about 87349 dots along 349.394 mm of strokes, more than a plan may hold "
       "(50000); raise --pitch or shorten the text"},
  });
}

// Refused before anything is fired: nothing printed on stdout, no file.
TEST(CliRefusal, MarkOptions) {
  expect_refusals({
      {{"mark", "X", "--run-in", "-1"}, "--run-in: -1 is outside the range 0 to 10 mm"},
      {{"mark", "SERIAL 2026-000123", "--height", "8"},
       "the text layout leaves the field by 49.720 mm at the right: it spans x 0.945 to 104.720 mm, y 0.000 to "
       "8.000 mm; the field is 110.000 mm square (±55.000 mm); lower --height, move the text with --x, --y or "
       "--align, or enlarge --field"},
      {{"mark", "X", "--run-out", "1e300"}, "--run-out: 1e300 is outside the range 0 to 10 mm"},
      {{"mark", "X", "--tick", "0"}, "--tick: 0 is outside the range 1 to 24 µs (20 % of head SL10's τ)"},
      {{"mark", "X", "--speed", "1e300"},
       "--speed: 1e300 is outside the range 0.001 to 19200 mm/s (head SL10's positioning limit)"},
      {{"mark", "X", "--speed", "fast", "--head", "SL14"},
       "--speed: 'fast' is neither auto nor a number (range: 0.001 to 16000 mm/s (head SL14's positioning "
       "limit))"},
      {{"mark", "X", "--jump-speed", "1e9"},
       "--jump-speed: 1e+09 is outside the range 1 to 19200 mm/s (head SL10's positioning limit)"},
      {{"mark", "X", "--jump-speed", "50000"},
       "--jump-speed: 50000 is outside the range 1 to 19200 mm/s (head SL10's positioning limit)"},
      {{"mark", "X", "--dose-png", "OUT/dose.svg"},
       "--dose-png '" + (temp_dir() / "out/dose.svg").string() + "': the name must end in .png"},
      {{"mark", "X", "--preview", "OUT/x.png", "--trace", "/nonexistent-dir/t.csv"},
       "--trace '/nonexistent-dir/t.csv': directory '/nonexistent-dir': No such file or directory"},
  });
}

// `job new` takes the same ranges a job file has (marker/limits/), named by the option.
TEST(CliRefusal, JobNewAndSerialOptions) {
  expect_refusals({
      {{"job", "new", "-o", "OUT/j.json", "--text", "SN {serial}", "--power", "150"},
       "--power: 150 is outside the range 0 to 100 %"},
      {{"job", "new", "-o", "OUT/j.json", "--text", "SN {serial}", "--frequency", "0"},
       "--frequency: 0 is outside the range 1 to 4000 kHz"},
      {{"job", "new", "-o", "OUT/j.json", "--text", "SN {serial}", "--passes", "1.5"},
       "--passes: '1.5' is not a whole number (range: 1 to 100)"},
      {{"job", "new", "-o", "OUT/j.json", "--text", "SN {serial}", "--width", "65"},
       "--width: 65 is outside the range 0 to 64"},
      {{"job", "new", "-o", "OUT/j.json", "--text", "SN {serial}", "--height", "1e9"},
       "--height: 1e9 is outside the range 0.01 to 10000 mm"},
      {{"job", "new", "-o", "OUT/j.txt", "--text", "A"},
       "--output '" + (temp_dir() / "out/j.txt").string() + "': the name must end in .json"},
      // Limits that depend on the head are the job file's, in the same words.
      {{"job", "new", "-o", "OUT/j.json", "--text", "A", "--speed", "20000"},
       "--speed: 20000 is outside the range 0.001 to 19200 mm/s (head SL10's positioning limit)"},
      {{"job", "new", "-o", "OUT/j.json", "--text", "A", "--jump-speed", "20000"},
       (temp_dir() / "out/j.json").string() +
           ": pens.default.jump_speed_mm_s: 20000 is outside the range 1 to 19200 mm/s (head SL10's positioning "
           "limit)"},
      {{"serial", "reserve", "sn", "0", "--store", "OUT/s.sqlite"}, "count: 0 is outside the range 1 to 1000000"},
  });
}

TEST(CliRefusal, AmbiguousFontNamesAreRefused) {
  if (!fs::exists("/usr/share/hershey-fonts/cursive.jhf") || !fs::exists("/usr/share/librecad/fonts/cursive.lff"))
    GTEST_SKIP() << "needs hershey-fonts-data and librecad-data (scripts/setup.sh)";
  expect_refusals({{{"layout", "X", "--font", "cursive"},
                    "font 'cursive' matches 2 installed files (/usr/share/hershey-fonts/cursive.jhf, "
                    "/usr/share/librecad/fonts/cursive.lff); name it with its extension (cursive.jhf) or give its "
                    "path"}});
  for (const char* name : {"cursive.jhf", "cursive.lff"})
    EXPECT_EQ(test::run_cli({"layout", "X", "--font", name}).code, 0) << name;
}

// Every option that takes a number has a range in --help and is checked; the list is the app's,
// nested subcommands (job new, serial set) included.
void count_ranged(const CLI::App& app, const std::string& command, int& numeric) {
  for (const CLI::Option* o : app.get_options()) {
    const std::string type = o->get_type_name();
    if (type.rfind("FLOAT", 0) != 0 && type.rfind("INT", 0) != 0 && type.rfind("UINT", 0) != 0) continue;
    ++numeric;
    EXPECT_TRUE(cli::registered_range(*o).has_value())
        << "marker" << command << " " << o->get_name() << " has no documented range";
  }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    count_ranged(*sub, command + " " + sub->get_name(), numeric);
}

TEST(CliRefusal, EveryNumericOptionHasARange) {
  CLI::App app;
  std::vector<cli::Command> commands = cli::all_commands();
  for (cli::Command& c : commands) c.attach(app);
  int numeric = 0;
  count_ranged(app, "", numeric);
  EXPECT_GT(numeric, 60);
}

}  // namespace
}  // namespace mark
