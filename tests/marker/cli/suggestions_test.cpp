// "Did you mean": a mistyped option or command is one line naming the closest one the command
// takes, and nothing runs.
#include "marker/cli/suggestions.hpp"

#include <gtest/gtest.h>

#include "tests/marker/cli_runner.hpp"

namespace mark::cli {
namespace {

TEST(Suggestions, TheClosestNameWithinASlip) {
  const std::vector<std::string> known = {"--height", "--head", "--font", "--field", "--hatch-angle"};
  EXPECT_EQ(closest_name("--hieght", known), "--height");  // two letters swapped: one edit
  EXPECT_EQ(closest_name("--heigth", known), "--height");
  EXPECT_EQ(closest_name("--hed", known), "--head");
  EXPECT_EQ(closest_name("--fnot", known), "--font");
  EXPECT_EQ(closest_name("--hatch-angel", known), "--hatch-angle");
  // Too far from any: no suggestion rather than a wrong one.
  EXPECT_EQ(closest_name("--bogusoption", known), std::nullopt);
  EXPECT_EQ(closest_name("--x", known), std::nullopt);
  EXPECT_EQ(closest_name("-x", {"-h", "-o"}), std::nullopt);
}

TEST(Suggestions, AMistypedOptionNamesTheCommandAndTheClosestOption) {
  const test::CliResult r = test::run_cli({"mark", "A", "--hieght", "3", "--virtual-time"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "marker: mark: unknown option --hieght (did you mean --height?)\n");
  EXPECT_EQ(r.out, "");
  const test::CliResult far = test::run_cli({"mark", "A", "--bogusoption", "1"});
  EXPECT_EQ(far.err, "marker: mark: unknown option --bogusoption\n");
  const test::CliResult valued = test::run_cli({"gcode", "A", "-o", "/nonexistent/x.ngc", "--tool-diametr=2"});
  EXPECT_EQ(valued.err, "marker: gcode: unknown option --tool-diametr (did you mean --tool-diameter?)\n");
}

TEST(Suggestions, AMistypedCommandNamesTheClosestCommand) {
  EXPECT_EQ(test::run_cli({}).err, "marker: give a command; `marker --help` lists them\n");
  EXPECT_EQ(test::run_cli({"lmc"}).err, "marker: lmc: give a command; `marker lmc --help` lists them\n");
  const test::CliResult top = test::run_cli({"mrak", "A"});
  EXPECT_EQ(top.code, 1);
  EXPECT_EQ(top.err, "marker: 'mrak' is not a command (did you mean mark?); `marker --help` lists them\n");
  const test::CliResult sub = test::run_cli({"serial", "craete", "sn"});
  EXPECT_EQ(sub.code, 1);
  EXPECT_EQ(sub.err,
            "marker: serial: 'craete' is not a command (did you mean create?); `marker serial --help` lists them\n");
}

}  // namespace
}  // namespace mark::cli
