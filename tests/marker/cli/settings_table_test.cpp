// One declaration per setting (marker/limits/setting.hpp): every option of every command and
// every key a job file is read by comes from a settings table; the command line and job files
// accept the same range for each setting and refuse in the same words; the library's own
// defaults are the tables'; and the docs' option tables are the tables, printed.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "base/error.hpp"
#include "driver/device.hpp"
#include "driver/sim/head_model.hpp"
#include "marker/cli/commands.hpp"
#include "tests/marker/cli_runner.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/layout/layout.hpp"
#include "marker/limits/setting_tables.hpp"
#include "marker/plan/pen.hpp"
#include "marker/production/job_file.hpp"
#include "marker/production/json_reader.hpp"
#include "marker/cnc/cut_settings.hpp"
#include "marker/cnc/gcode_options.hpp"
#include "marker/cnc/tool/tool_measure.hpp"
#include "marker/codes/code_marks.hpp"
#include "marker/codes/code_spec.hpp"
#include "marker/codes/verify.hpp"
#include "marker/job/code_photo.hpp"
#include "marker/cnc/vcarve.hpp"
#include "marker/fill/fill_options.hpp"
#include "marker/gravure/cell_setup.hpp"
#include "marker/gravure/gravure_job.hpp"
#include "marker/gravure/head_design.hpp"
#include "marker/gravure/screen.hpp"
#include "marker/peen/gantry.hpp"
#include "driver/sim/sim_stylus_head.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

std::vector<SettingRef> all_settings() {
  std::vector<SettingRef> out;
  for (const SettingTable* t : kSettingTables) out.insert(out.end(), t->settings.begin(), t->settings.end());
  return out;
}

// Options that are not settings: what a command reads and writes, how it reports, and the run
// around a job (its store, its fault injection). Everything else a command takes is a setting.
const std::set<std::string> kNotSettings = {
    "--help", "--json", "--csv",                            // how the result is reported
    "--output", "--preview", "--dose-png", "--trace",       // files written
    "--force",                                              // ... over an existing one
    "--job", "--store", "--mask", "--tool-image",           // files and stores read
    "--inject",                                             // faults injected into a run (tests, drills)
    "--compare", "--no-serial", "--quiet",                  // what a report includes
    "--cleanup-output", "--camera-png", "--picture",        // more files written
    "--pattern", "--from-image",                            // more files read
    "--markdown",                                           // how `marker options` prints
};

struct Found {
  std::string command;
  const CLI::Option* option;
};

void collect(const CLI::App& app, const std::string& command, std::vector<Found>& out) {
  for (const CLI::Option* o : app.get_options()) out.push_back({command, o});
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    collect(*sub, command + " " + sub->get_name(), out);
}

std::vector<Found> every_option() {
  static CLI::App app;  // the options keep pointers into the commands' arguments
  static std::vector<cli::Command> commands = [] {
    std::vector<cli::Command> c = cli::all_commands();
    for (cli::Command& command : c) command.attach(app);
    return c;
  }();
  std::vector<Found> out;
  collect(app, "marker", out);
  return out;
}

// The setting an option was registered from: its flag (or the flag with "code-" after the
// dashes, for `mark --code-…`) and exactly the description add_setting gives it.
std::optional<SettingRef> setting_of(const CLI::Option& o) {
  const std::string name = o.get_name();
  for (const SettingRef& s : all_settings()) {
    std::string flag(name_of(s).flag);
    flag = flag.substr(0, flag.find(','));
    const bool named = name == flag || (name.starts_with("--code-") && flag.starts_with("--") &&
                                        name == "--code-" + flag.substr(2));
    // A number-or-word option (`--speed auto`) adds the word to the setting's help.
    const std::string desc = o.get_description();
    if (named && (desc == cli::setting_description(s) || desc.starts_with(std::string(name_of(s).help) + "; or ")))
      return s;
  }
  return std::nullopt;
}

// Options that do not come from a settings table yet: the tables they belong to come next.
const std::set<std::string> kPending = {
};

TEST(Settings, EveryOptionOfEveryCommandIsDeclared) {
  int declared = 0;
  for (const Found& f : every_option()) {
    const CLI::Option& o = *f.option;
    if (!o.nonpositional()) continue;  // TEXT, IMAGE, …: what the command works on
    const std::string name = o.get_name();
    if (setting_of(o)) {
      ++declared;
      continue;
    }
    if (kNotSettings.count(name) || kPending.count(f.command + " " + name)) continue;
    ADD_FAILURE() << f.command << " " << name << " is not declared in any settings table (marker/limits/)";
  }
  EXPECT_GT(declared, 100);
}

// "objects[1].hatch.sets[0].angle_deg" → "objects[].hatch.sets[].angle_deg";
// "pens.fine.speed_mm_s" → "pens.NAME.speed_mm_s".
// A hatch set's keys ("….sets[].angle_deg") are the fill's own ("….angle_deg").
std::string generic_path(const std::string& path) {
  std::string p = std::regex_replace(path, std::regex(R"(\[[0-9]+\])"), "[]");
  for (std::size_t at = p.find(".sets[]."); at != std::string::npos; at = p.find(".sets[]."))
    p.erase(at, std::string_view(".sets[]").size());
  for (const char* named : {"pens.", "counters.", "variables.", "date_codes."}) {
    const std::string prefix = named;
    if (p.starts_with(prefix)) {
      const std::size_t dot = p.find('.', prefix.size());
      p = prefix + "NAME" + (dot == std::string::npos ? "" : p.substr(dot));
    }
  }
  return p;
}

// Every key the tables declare, as generic paths.
std::map<std::string, SettingRef> declared_keys() {
  std::map<std::string, SettingRef> keys;
  for (const SettingTable* t : kSettingTables)
    for (const SettingRef& s : t->settings) {
      const std::string key(name_of(s).key);
      if (key.empty()) continue;
      std::string_view places = t->place;
      while (true) {
        const std::size_t comma = places.find(", ");
        const std::string place(places.substr(0, comma));
        keys.emplace(place.empty() ? key : place + "." + key, s);
        if (comma == std::string_view::npos) break;
        places.remove_prefix(comma + 2);
      }
    }
  return keys;
}

// Keys that are not settings: the file's structure (its objects, lists and names) and text
// keys with no command-line option.
const std::set<std::string> kStructure = {
    "format", "name", "shifts[].code", "shifts[].start", "variables.NAME", "counters", "pens", "objects",
    "head.model", "data", "data.file", "data.delimiter", "objects[].kind", "objects[].symbology", "objects[].fill", "objects[].hatch",
    "objects[].fill.sets", "objects[].hatch.sets", "pens.NAME", "counters.NAME", "objects[].require",
    "date_codes", "date_codes.NAME", "date_codes.NAME.unit", "date_codes.NAME.codes",
};
// Declared for a place that does not read it: a code's hatch fills square modules, where the fill
// rule makes no difference.
const std::set<std::string> kNotReadThere = {"objects[].hatch.rule"};

// A job with every kind of object a reader descends into, so the census sees every reader.
constexpr const char* kEveryReader = R"({
  "format": "marker-job/1", "name": "census", "device": "sim",
  "head": {"model": "SL10", "spot_diameter_um": 40}, "field_mm": 100, "time_zone": "UTC",
  "shifts": [{"code": "A", "start": "06:00"}], "variables": {"lot": "A1"},
  "counters": {"sn": {"start": 1, "digits": "0123456789"}},
  "date_codes": {"m": {"unit": "month", "codes": ["A", "B"]}},
  "pens": {"p": {"speed_mm_s": 500}},
  "objects": [
    {"name": "t", "pen": "p", "template": "{sn} {var:lot} {shift}", "circle": {"radius_mm": 20},
     "fill": {"sets": [{"angle_deg": 0}]}, "require": {"quality": "good"}},
    {"name": "c", "kind": "code", "pen": "p", "symbology": "datamatrix", "template": "{sn}",
     "hatch": {"sets": [{"angle_deg": 0}]}, "require": {"code": "read", "code_grade": "C"}}
  ]
})";

std::set<std::string> census_of(const std::string& job) {
  std::vector<std::string> asked;
  JsonReader::census = &asked;
  try {
    parse_job(job, "census.json");
  } catch (...) {
    JsonReader::census = nullptr;
    throw;
  }
  JsonReader::census = nullptr;
  std::set<std::string> out;
  for (const std::string& a : asked) out.insert(generic_path(a));
  return out;
}

TEST(Settings, EveryKeyAJobFileIsReadByIsDeclared) {
  const std::map<std::string, SettingRef> declared = declared_keys();
  const std::set<std::string> asked = census_of(kEveryReader);
  EXPECT_GT(asked.size(), 60u);
  for (const std::string& key : asked)
    EXPECT_TRUE(declared.count(key) || kStructure.count(key))
        << "job-file key " << key << " is not declared in any settings table (marker/limits/)";
  // And the other way round: every key a table declares is read.
  for (const auto& [key, s] : declared)
    EXPECT_TRUE(asked.count(key) || kNotReadThere.count(key)) << key << " is declared but never read";
}

// A job file with one key set to a value: at the top level, in the head object, the pen or the
// text object, as the setting's place says.
std::string job_with(const std::string& place, const std::string& key, const std::string& value) {
  std::string top = "", head = "", pen = "", object = "", circle = "";
  // A delays setting is read by a delays pen only (a blanking pen refuses it).
  std::string corner = "blanking";
  for (const SettingRef& s : kDelaysPenSettings)
    if (place == "pens.NAME" && name_of(s).key == key) corner = "delays";
  const std::string item = "\"" + key.substr(key.rfind('.') + 1) + "\": " + value;
  if (key.starts_with("head.")) head = ", " + item;
  else if (key.starts_with("circle.")) circle = ", " + item;
  else if (key.starts_with("require.")) object = ", \"require\": {" + item + "}";
  else if (place == "pens.NAME") pen = ", " + item;
  else if (place == "objects[]") object = ", " + item;
  else top = ", " + item;
  return R"({"format": "marker-job/1", "head": {"model": "SL10")" + head + "}" + top +
         R"(, "pens": {"p": {"corner": ")" + corner + "\"" + pen + R"(}}, "objects": [{"name": "t", "template": "A")" +
         object + (circle.empty() ? "" : R"(, "circle": {"radius_mm": 20)" + circle + "}") + "}]}";
}

std::string job_error(const std::string& text) {
  try {
    parse_job(text, "j.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The command line's refusal while parsing (nothing runs): "" when accepted.
std::string cli_error(const std::vector<std::string>& args) {
  CLI::App app;
  std::vector<cli::Command> commands = cli::all_commands();
  for (cli::Command& c : commands) c.attach(app);
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  return "";
}

// The command line's refusal when the command runs (a refusal comes before anything is
// marked): "" when it ran. For the settings checked once the head is known.
std::string run_error(const std::vector<std::string>& args) {
  const test::CliResult r = test::run_cli(args);
  if (r.code == 0) return "";
  std::string err = r.err;
  if (err.starts_with("marker: ")) err.erase(0, 8);
  while (!err.empty() && err.back() == '\n') err.pop_back();
  return err;
}

// The command each table's options are given to, with its required arguments.
std::vector<std::string> command_for(const std::string& flag) {
  if (flag == "--spot" || flag == "--passes")
    return {"job", "new", "-o", test::fresh_temp_file("marker_settings_table", "x.json").string(), "--text", "A"};
  return {"mark", "A"};
}

// For every number that has both an option and a key: its ends are accepted and just beyond
// them it is refused, by both, each naming the same range. A speed or the tick is limited by the
// head too: the command line checks it once the head is known, and both name the head's limit in
// the same words.
TEST(Settings, CommandLineAndJobFilesAcceptTheSameRanges) {
  const HeadModel sl10 = head_sl10();
  int checked = 0;
  for (const SettingTable* t : kSettingTables)
    for (const SettingRef& ref : t->settings) {
      const auto* q = std::get_if<const Quantity*>(&ref);
      if (!q || (*q)->name.flag.empty() || (*q)->name.key.empty()) continue;
      // Not yet covered here: the fill's keys (in a "fill" object of their own), a code object's
      // (`mark --code-…`, in a code object) and the circle's start angle (which needs --circle
      // too); their ranges are the same declaration either way.
      if (t->place.find("fill") != std::string_view::npos || t->id == "code" ||
          (*q)->name.key == "circle.start_angle_deg")
        continue;
      const Quantity& s = **q;
      const std::string flag(s.name.flag), key(s.name.key);
      const bool head_limited = &s == &kMarkSpeed || &s == &kJumpSpeed || &s == &kJoinSpeed || &s == &kTick;
      const Range job_range = &s == &kTick ? head_tick_range(sl10) : head_limited ? head_speed_range(s, sl10) : s.range();
      const double below = s.bounds.min - std::max(1e-3, std::abs(s.bounds.min) * 0.5);
      const double above = s.bounds.max * (s.bounds.max > 0 ? 2 : 0.5) + 1;
      std::vector<std::string> args = command_for(flag);
      const auto with_value = [&](double v) {
        std::vector<std::string> a = args;
        a.push_back(flag);
        a.push_back(format_number(v));
        return a;
      };
      SCOPED_TRACE(flag + " / " + key);
      ++checked;
      // The lowest value: accepted by both (the layout checks positions against the field later).
      if (!s.bounds.above_min) {
        EXPECT_EQ(cli_error(with_value(s.bounds.min)), "");
        EXPECT_EQ(job_error(job_with(std::string(t->place), key, format_number(s.bounds.min))), "");
      }
      for (double v : {below, above}) {
        if (s.bounds.zero_means && v == 0) continue;
        const std::string typed = format_number(v);
        const std::string cli = head_limited ? run_error(with_value(v)) : cli_error(with_value(v));
        EXPECT_EQ(cli, flag + ": " + typed + " is outside the range " + job_range.text());
        const std::string job = job_error(job_with(std::string(t->place), key, typed));
        EXPECT_TRUE(job.ends_with(": " + typed + " is outside the range " + job_range.text())) << job;
      }
    }
  EXPECT_GE(checked, 25);
}

// The issue's four disagreements, one by one: the same refusal (or acceptance) from a job file's
// pen and from `marker mark`, word for word after the place it names.
TEST(Settings, TheFormerDisagreementsNowAgree) {
  const std::string sl10 = " mm/s (head SL10's positioning limit)";
  EXPECT_EQ(cli_error({"mark", "A", "--jump-settle-um", "5000"}),
            "--jump-settle-um: 5000 is outside the range 0 to 1000 µm");
  EXPECT_EQ(job_error(job_with("pens.NAME", "jump_settle_um", "5000")),
            "j.json: pens.p.jump_settle_um: 5000 is outside the range 0 to 1000 µm");
  EXPECT_EQ(run_error({"mark", "A", "--jump-speed", "0.5"}), "--jump-speed: 0.5 is outside the range 1 to 19200" + sl10);
  EXPECT_EQ(job_error(job_with("pens.NAME", "jump_speed_mm_s", "0.5")),
            "j.json: pens.p.jump_speed_mm_s: 0.5 is outside the range 1 to 19200" + sl10);
  EXPECT_EQ(cli_error({"mark", "A", "--settle-um", "0"}), "");
  EXPECT_EQ(job_error(job_with("pens.NAME", "settle_um", "0")), "");
  EXPECT_EQ(cli_error({"mark", "A", "--join-speed", "0"}), "");
  EXPECT_EQ(job_error(job_with("pens.NAME", "join_speed_mm_s", "0")), "");
}

// `mark --speed` is checked in one place, with the range a job file's pen speed has on the same
// head: one text whichever way the speed is given (a number, a word that is neither, on another
// head), and `job new --speed` writes nothing its reader would refuse.
TEST(Settings, MarkSpeedHasOneRangeText) {
  const std::string sl10 = "0.001 to 19200 mm/s (head SL10's positioning limit)";
  const std::string sl14 = "0.001 to 16000 mm/s (head SL14's positioning limit)";
  for (const char* v : {"0", "20000"}) {
    SCOPED_TRACE(v);
    const std::string tail = std::string(v) + " is outside the range " + sl10;
    EXPECT_EQ(run_error({"mark", "A", "--speed", v}), "--speed: " + tail);
    EXPECT_EQ(job_error(job_with("pens.NAME", "speed_mm_s", v)), "j.json: pens.p.speed_mm_s: " + tail);
    EXPECT_EQ(run_error({"code", "datamatrix", "A", "--speed", v}), "--speed: " + tail);
  }
  EXPECT_EQ(run_error({"mark", "A", "--speed", "17000", "--head", "SL14"}),
            "--speed: 17000 is outside the range " + sl14);
  EXPECT_EQ(run_error({"mark", "A", "--speed", "fast", "--head", "SL14"}),
            "--speed: 'fast' is neither auto nor a number (range: " + sl14 + ")");
  const fs::path out = test::fresh_temp_file("settings_speed", "j.json");
  EXPECT_EQ(run_error({"job", "new", "-o", out.string(), "--text", "A", "--speed", "20000"}),
            "--speed: 20000 is outside the range " + sl10);
  EXPECT_FALSE(fs::exists(out));
}

TEST(Settings, HeadPresetsAreTheSimulatorsPresets) {
  std::string names;
  for (const std::string& n : head_names()) names += (names.empty() ? "" : ", ") + n;
  EXPECT_NE(std::string(kHead.name.help).find("preset: " + names + " ("), std::string::npos) << kHead.name.help;
  EXPECT_TRUE(find_head(kHead.value));
}

// What a library caller gets without giving a setting is what the tables say a user gets.
TEST(Settings, TheLibrarysDefaultsAreTheTables) {
  const LayoutOptions layout;
  EXPECT_EQ(layout.height_mm, kHeight.fallback());
  EXPECT_EQ(layout.width_factor, kWidthFactor.fallback());
  EXPECT_EQ(layout.gap_mm, kGap.fallback());
  EXPECT_EQ(layout.line_spacing, kLineSpacing.fallback());
  EXPECT_EQ(layout.angle_deg, kAngle.fallback());
  EXPECT_EQ(layout.italic_deg, kItalic.fallback());
  EXPECT_EQ(layout.base.x(), kX.fallback());
  const LaserSettings laser;
  EXPECT_EQ(laser.power_pct, kPower.fallback());
  EXPECT_EQ(laser.frequency_khz, kFrequency.fallback());
  EXPECT_EQ(laser.pulse_width_ns, kPulseWidth.fallback());
  EXPECT_EQ(JobPen{}.passes, kPasses.fallback());
  const PenRules rules;
  EXPECT_EQ(rules.blank_angle_deg, kBlankAngle.fallback());
  EXPECT_EQ(rules.settle_um, kSettle.fallback());
  EXPECT_EQ(rules.junction_dv_mm_s, kJunctionDv.fallback());
  EXPECT_EQ(Pen{}.mark_speed_mm_s, kMarkSpeed.fallback());
  EXPECT_EQ(Pen{}.tick_s * 1e6, kTick.fallback());
  const HeadModel sl10 = head_sl10();
  EXPECT_EQ(sl10.field_mm, kField.fallback());
  EXPECT_EQ(sl10.spot_diameter_um, kSpot.fallback());
  EXPECT_EQ(std::string(to_string(CornerStrategy::blanking)), kCorner.value);
  const FillOptions fill;
  EXPECT_EQ(fill.sets.front().spacing_mm, kHatchSpacing.fallback());
  EXPECT_EQ(fill.sets.front().angle_deg, kHatchAngle.fallback());
  EXPECT_EQ(fill.contour_passes, kContourPasses.fallback());
  const CodeLayout code;
  EXPECT_EQ(format_number(kDefaultModule_mm), kModule.derived);
  EXPECT_EQ(code.dot_share, kDotSize.fallback());
  EXPECT_EQ(CodeSpec{}.qr_ecc, kQrEcc.value.front());
  const CodeCheckOptions verify;
  EXPECT_EQ(verify.response.spot_diameter_mm, kBeamDiameter.fallback());
  EXPECT_EQ(verify.response.reference_width_mm, kLineWidth.fallback());
  EXPECT_EQ(verify.response.reference_speed_mm_s, kLineSpeed.fallback());
  EXPECT_EQ(verify.reading.aperture_modules, kAperture.fallback());
  const GantryConfig gantry;
  EXPECT_EQ(gantry.x.steps_per_mm, kStepsPerMm.fallback());
  EXPECT_EQ(gantry.x.max_speed_mm_s, kGantrySpeed.fallback());
  EXPECT_EQ(gantry.x.accel_mm_s2, kGantryAccel.fallback());
  EXPECT_EQ(gantry.strike_s * 1000, kStrike.fallback());
  const VCarveSettings vcarve;
  EXPECT_EQ(vcarve.bit_angle_deg, kBitAngle.fallback());
  EXPECT_EQ(vcarve.tolerance_mm, kCarveTolerance.fallback());
  const CutSettings cut;
  EXPECT_EQ(cut.tool_diameter_mm, kToolDiameter.fallback());
  EXPECT_EQ(cut.depth_mm, kDepth.fallback());
  EXPECT_EQ(cut.depth_per_pass_mm, kDepthPerPass.fallback());
  EXPECT_EQ(cut.safe_z_mm, kSafeZ.fallback());
  EXPECT_EQ(cut.feed_mm_min, kFeed.fallback());
  EXPECT_EQ(cut.plunge_feed_mm_min, kPlungeFeed.fallback());
  EXPECT_EQ(cut.arcs.tolerance_mm, kArcTolerance.fallback());
  EXPECT_EQ(GcodeOptions{}.spindle_rpm, kSpindle.fallback());
  EXPECT_EQ(ToolMeasureOptions{}.tangential_angle_deg, kTangentialAngle.fallback());
  const GravureSetup setup;
  EXPECT_EQ(setup.ct.full_cell_depth_um, kCtDepth.fallback());
  EXPECT_EQ(setup.ct.channel_depth_um, kCtChannel.fallback());
  EXPECT_EQ(setup.lw.full_cell_depth_um, kLwDepth.fallback());
  EXPECT_EQ(setup.lw.channel_depth_um, kLwChannel.fallback());
  EXPECT_EQ(setup.lift_um, kLift.fallback());
  const GravureScreen screen;
  EXPECT_EQ(format_number(screen.cells_per_mm_along * 10), kScreen.value);
  EXPECT_EQ(screen.cell_rate_hz, kCellRate.fallback());
  EXPECT_EQ(GravureJobSpec{}.stylus_angle_deg, kStylusAngle.fallback());
  EXPECT_EQ(TargetResponse{}.corner_hz, kTargetCorner.fallback());
  EXPECT_EQ(SimStylusHeadOptions{}.sense_noise_um, kSenseNoise.fallback());
  EXPECT_EQ(SimStylusHeadOptions{}.sense_velocity_noise_um_s, kSenseVelocityNoise.fallback());
  EXPECT_EQ(to_string(AutoTuneOptions{}.source), kTuneFrom.value);
  const CounterSpec counter;
  EXPECT_EQ(counter.start, kCounterStart.fallback());
  EXPECT_EQ(counter.step, kCounterStep.fallback());
  EXPECT_EQ(counter.marks_per_serial, kMarksPerSerial.fallback());
  EXPECT_EQ(counter.width, kCounterWidth.fallback());
}

// The docs hold each table between <!-- settings: ID --> and <!-- end settings -->, exactly as
// `marker options --markdown ID` prints it (scripts/docs_tables.sh rewrites them).
TEST(Settings, TheDocsTablesAreTheTables) {
  std::set<std::string> shown;
  const std::regex block(R"(<!-- settings: ([a-z-]+) -->\n([^]*?)<!-- end settings -->)");
  for (const auto& entry : fs::directory_iterator(fs::path(MARKER_SOURCE_DIR) / "docs")) {
    if (entry.path().extension() != ".md") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    for (std::sregex_iterator it(doc.begin(), doc.end(), block), end; it != end; ++it) {
      const std::string id = (*it)[1];
      const SettingTable* t = find_setting_table(id);
      ASSERT_NE(t, nullptr) << entry.path() << " shows a table '" << id << "' that does not exist";
      EXPECT_EQ((*it)[2].str(), markdown_table(*t))
          << entry.path().filename() << ": the '" << id << "' table differs from marker/limits/ "
          << "(scripts/docs_tables.sh rewrites it)";
      shown.insert(id);
    }
  }
  for (const SettingTable* t : kSettingTables)
    EXPECT_TRUE(shown.count(std::string(t->id))) << "no docs page shows the '" << t->id << "' table";
}

}  // namespace
}  // namespace mark
