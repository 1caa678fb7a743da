// `marker gcode` and `marker tool-measure` end to end, in-process, with the built-in font and
// the real layout: every program the command writes — all dialects, both modes, linear /
// inclined / circular fitting, mirrored, sheared, width factor (ellipses), inch — is
// interpreted by LinuxCNC's rs274 and checked against the same Figure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../cli_runner.hpp"
#include "cnc_checks.hpp"
#include "cnc_files.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/cnc/protrusion.hpp"
#include "tool_render.hpp"

namespace mark::test {
namespace {

namespace fs = std::filesystem;

std::string out_path(const std::string& name) { return cnc_out_path("cnc_cli", name); }

// The number printed right after `label`, or NaN.
double number_after(const std::string& text, const std::string& label) {
  const std::size_t at = text.find(label);
  return at == std::string::npos ? std::nan("") : std::strtod(text.c_str() + at + label.size(), nullptr);
}

// The layout part of a command line, and the same as LayoutArgs for building the Figure here.
struct Fitting {
  std::string name;
  std::vector<std::string> args;
  cli::LayoutArgs layout;
};

std::vector<Fitting> fittings() {
  std::vector<Fitting> f;
  cli::LayoutArgs base;
  base.height_mm = 5;
  {
    Fitting x{"linear", {"--height", "5", "--x", "-15"}, base};
    x.layout.x_mm = -15;
    f.push_back(x);
  }
  {
    Fitting x{"inclined", {"--height", "5", "--x", "-12", "--y", "-5", "--angle", "20"}, base};
    x.layout.x_mm = -12, x.layout.y_mm = -5, x.layout.angle_deg = 20;
    f.push_back(x);
  }
  {
    Fitting x{"circular", {"--height", "5", "--circle", "0,0,20", "--self-centred"}, base};
    x.layout.circle = "0,0,20", x.layout.self_centred = true;
    f.push_back(x);
  }
  {
    Fitting x{"mirrored", {"--height", "5", "--x", "-15", "--mirror"}, base};
    x.layout.x_mm = -15, x.layout.mirror = true;
    f.push_back(x);
  }
  {
    Fitting x{"sheared", {"--height", "5", "--x", "-15", "--italic", "15", "--width-factor", "0.8"}, base};
    x.layout.x_mm = -15, x.layout.italic_deg = 15, x.layout.width_factor = 0.8;
    f.push_back(x);
  }
  return f;
}

const char* kText = "R2-D9 ok";

TEST(GcodeCli, DepressionProgramsPassRs274AndFollowTheStrokes) {
  REQUIRE_RS274();
  for (const Fitting& fit : fittings())
    for (const char* dialect : {"linuxcnc", "fanuc", "plain"}) {
      SCOPED_TRACE(fit.name + " " + dialect);
      const std::string file = out_path(std::string("dep_") + fit.name + "_" + dialect + ".ngc");
      std::vector<std::string> args = {"gcode", kText, "--mode", "depression", "--tool-diameter", "0.4",
                                       "--depth", "0.2", "--depth-per-pass", "0.1", "--dialect", dialect,
                                       "-o", file};
      args.insert(args.end(), fit.args.begin(), fit.args.end());
      const CliResult r = run_cli(args);
      ASSERT_EQ(r.code, 0) << r.err;
      const Figure fig = cli::build_figure(kText, fit.layout).figure;
      const Rs274Run run = run_rs274(slurp(file), std::string("cli_dep_") + fit.name + "_" + dialect);
      ASSERT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;
      CutSettings s;
      s.depth_mm = 0.2;
      const DepressionCheck c = check_depression(fig, run, s, 0.0001);
      EXPECT_GT(c.arcs, 10u);
    }
}

TEST(GcodeCli, InchProgram) {
  REQUIRE_RS274();
  const std::string file = out_path("dep_inch.ngc");
  const CliResult r = run_cli({"gcode", kText, "--height", "5", "--x", "-15", "--italic", "10", "--depth", "0.254",
                               "--units", "inch", "--dialect", "fanuc", "-o", file});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string program = slurp(file);
  EXPECT_NE(program.find("G20"), std::string::npos);
  EXPECT_NE(program.find("Z-0.01 "), std::string::npos);  // 0.254 mm
  cli::LayoutArgs l;
  l.height_mm = 5, l.x_mm = -15, l.italic_deg = 10;
  const Rs274Run run = run_rs274(program, "cli_dep_inch");
  ASSERT_EQ(run.exit_code, 0) << run.errors;
  CutSettings s;
  s.depth_mm = 0.254;
  check_depression(cli::build_figure(kText, l).figure, run, s, 0.0013);
}

TEST(GcodeCli, ProtrusionProgramsPassRs274WithoutGouging) {
  REQUIRE_RS274();
  const std::vector<Fitting> all = fittings();
  const char* dialects[] = {"linuxcnc", "fanuc", "plain"};
  for (std::size_t k = 0; k < all.size(); ++k) {
    const Fitting& fit = all[k];
    const char* dialect = dialects[k % 3];
    SCOPED_TRACE(fit.name + " " + dialect);
    const std::string file = out_path(std::string("prot_") + fit.name + ".ngc");
    const std::string preview = out_path(std::string("prot_") + fit.name + ".svg");
    std::vector<std::string> args = {"gcode", "OK 42", "--mode", "protrusion", "--tool-diameter", "0.6",
                                     "--depth", "0.3", "--dialect", dialect, "-o", file, "--preview", preview};
    args.insert(args.end(), fit.args.begin(), fit.args.end());
    const CliResult r = run_cli(args);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("pocket loops"), std::string::npos);
    EXPECT_TRUE(fs::exists(preview));
    const Figure fig = cli::build_figure("OK 42", fit.layout).figure;
    CutSettings s;
    s.tool_diameter_mm = 0.6;
    s.depth_mm = 0.3;
    const ProtrusionResult res = protrusion_toolpath(fig, s, {});
    const Rs274Run run = run_rs274(slurp(file), std::string("cli_prot_") + fit.name);
    ASSERT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;
    const ProtrusionCheck c = check_protrusion(fig, run, s, res);
    EXPECT_GE(c.closest_to_letters_mm, 0.3 - kClosenessTolMm);
    EXPECT_EQ(c.wider_than_tool, 0);
  }
}

// A worn tool measured from its shadow: the pocket is offset by the measured radius, so the
// tool centre keeps exactly that distance from the letters, which keep their designed width.
TEST(GcodeCli, ToolImageReplacesTheNominalRadius) {
  REQUIRE_RS274();
  Render rr;
  rr.size = 240;
  rr.blur_px = 1.0;
  rr.noise = 0.02;
  const std::string image = write_pgm(disk(rr, Point(120.3, 119.6), 92), "worn_cli");  // 0.92 mm at 5 µm
  const std::string file = out_path("prot_worn.ngc");
  const CliResult r = run_cli({"gcode", "IO", "--height", "5", "--mode", "protrusion", "--tool-diameter", "1.0",
                               "--depth", "0.2", "--tool-image", image, "--pixel-size", "5", "-o", file});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(number_after(r.out, "measured diameter "), 0.92, 0.002) << r.out;
  cli::LayoutArgs l;
  l.height_mm = 5;
  const Figure fig = cli::build_figure("IO", l).figure;
  CutSettings s;
  s.tool_diameter_mm = 0.92;
  s.depth_mm = 0.2;
  ProtrusionSettings ps;
  ps.stroke_width_mm = 1.0;  // the nominal tool's
  const ProtrusionResult res = protrusion_toolpath(fig, s, ps);
  const Rs274Run run = run_rs274(slurp(file), "cli_prot_worn");
  ASSERT_EQ(run.exit_code, 0) << run.errors;
  const ProtrusionCheck c = check_protrusion(fig, run, s, res);
  EXPECT_GE(c.closest_to_letters_mm, 0.46 - 0.002);
  EXPECT_LT(c.closest_to_letters_mm, 0.46 + 0.01);  // not the nominal 0.5
  EXPECT_EQ(c.wider_than_tool, 0);
}

TEST(GcodeCli, ToolMeasureReportsDiameterAndWear) {
  Render rr;
  rr.size = 240;
  rr.blur_px = 1.0;
  const std::string image = write_png(disk(rr, Point(120.3, 119.6), 92), "worn_measure");
  const CliResult r = run_cli({"tool-measure", image, "--pixel-size", "5", "--nominal-diameter", "1"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NEAR(number_after(r.out, "diameter "), 0.92, 0.002) << r.out;
  EXPECT_NEAR(number_after(r.out, "radius "), 0.46, 0.001) << r.out;
  EXPECT_NEAR(number_after(r.out, "mm: radius "), -0.04, 0.001) << r.out;
  const CliResult bad = run_cli({"tool-measure", "/nonexistent.png", "--pixel-size", "5"});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("marker: '/nonexistent.png': cannot open the image"), std::string::npos) << bad.err;
}

// The tool measurement as JSON, the same figures as the text, and the text says from which axis
// and in which direction the form deviation's angle is counted.
TEST(GcodeCli, ToolMeasureJsonAndTheAnglesAxis) {
  Render rr;
  rr.size = 240;
  const Point c(120.3, 119.6);
  const double radius = 92;
  const GrayImage img = chipped_disk(rr, c, radius, 30);  // a chip 8 px deep at 30°, y up
  const std::string image = write_png(img, "chipped_json");
  const CliResult j = run_cli({"tool-measure", image, "--pixel-size", "5", "--nominal-diameter", "1", "--json"});
  ASSERT_EQ(j.code, 0) << j.err;
  const auto m = nlohmann::json::parse(j.out);
  EXPECT_NEAR(m["diameter_mm"].get<double>(), 2 * radius * 0.005, 0.005);
  EXPECT_NEAR(m["center_x_mm"].get<double>(), c.x() * 0.005, 0.002);
  EXPECT_NEAR(m["center_y_mm"].get<double>(), c.y() * 0.005, 0.002);
  EXPECT_NEAR(m["form_deviation_angle_deg"].get<double>(), 30, 6);
  EXPECT_NEAR(m["form_deviation_mm"].get<double>(), 8 * 0.005, 1 * 0.005);
  EXPECT_NEAR(m["radius_deviation_mm"].get<double>(), radius * 0.005 - 0.5, 0.002);
  EXPECT_EQ(m["image"], image);
  const CliResult t = run_cli({"tool-measure", image, "--pixel-size", "5"});
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NEAR(number_after(t.out, "diameter "), m["diameter_mm"].get<double>(), 1e-4);
  EXPECT_NE(t.out.find("° (counter-clockwise from the image's +x axis (pointing right), y up)"), std::string::npos)
      << t.out;
}

// A 40-line text: the title carries every line, each in its own comment, and LinuxCNC runs it
// (it refused the one-line title with "Command too long").
TEST(GcodeCli, FortyLineTextRunsInEveryDialect) {
  REQUIRE_RS274();
  std::string text;
  for (int k = 0; k < 40; ++k) text += (k ? "\\n" : "") + std::string("L") + std::to_string(k) + " ABCDEFGHIJKLMNOPQRSTUVWXYZ";
  for (const char* dialect : {"linuxcnc", "fanuc", "plain"}) {
    const std::string file = out_path(std::string("forty_") + dialect + ".ngc");
    const CliResult r = run_cli({"gcode", text, "--height", "1", "--x", "-50", "--y", "50",
                                 "--dialect", dialect, "-o", file, "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const std::string program = slurp(file);
    EXPECT_EQ(j["lines"].get<std::size_t>(), static_cast<std::size_t>(std::count(program.begin(), program.end(), '\n')));
    EXPECT_EQ(j["dialect"], dialect);
    EXPECT_NE(program.find("L39 ABCDEFGHIJKLMNOPQRSTUVWXYZ)"), std::string::npos) << dialect;
    const Rs274Run run = run_rs274(program, std::string("forty_") + dialect);
    EXPECT_EQ(run.exit_code, 0) << dialect << ": " << run.errors;
  }
}

// Raised letters that run into each other at the default stroke width (the tool diameter) get a
// warning naming them and what to change; with room between them, none.
TEST(GcodeCli, WarnsWhenRaisedLettersRunIntoEachOther) {
  const std::string file = out_path("touching.ngc");
  const CliResult touching = run_cli({"gcode", "AB", "--mode", "protrusion", "--height", "2", "-o", file, "--json"});
  ASSERT_EQ(touching.code, 0) << touching.err;
  EXPECT_NE(touching.err.find("marker: warning: raised letters 'A' and 'B' run into each other at stroke width 1 mm"),
            std::string::npos)
      << touching.err;
  EXPECT_NE(touching.err.find("raise --gap or --height, or lower --stroke-width"), std::string::npos);
  const auto j = nlohmann::json::parse(touching.out);
  ASSERT_FALSE(j["warnings"].empty());
  const CliResult apart = run_cli({"gcode", "AB", "--mode", "protrusion", "--height", "2", "--gap", "1", "-o", file});
  ASSERT_EQ(apart.code, 0) << apart.err;
  EXPECT_EQ(apart.err.find("run into each other"), std::string::npos) << apart.err;
}

TEST(GcodeCli, BadInputIsOneLineAndNoFile) {
  const std::string file = out_path("never.ngc");
  for (std::vector<std::string> args :
       {std::vector<std::string>{"gcode", "A", "--mode", "emboss", "-o", file},
        {"gcode", "A", "--dialect", "heidenhain", "-o", file},
        {"gcode", "A", "--mode", "protrusion", "--cutter-comp", "--dialect", "plain", "-o", file},
        {"gcode", "A", "--depth", "-1", "-o", file},
        {"gcode", "A", "--mode", "protrusion", "--stepover", "5", "-o", file},
        {"gcode", "A", "--header", "M30%", "-o", file},
        {"gcode", "A", "--tool-image", "x.pgm", "-o", file},
        {"gcode", "   ", "-o", file}}) {
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.code, 1) << args[2];
    EXPECT_EQ(r.err.rfind("marker: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(file));
  }
}

}  // namespace
}  // namespace mark::test
