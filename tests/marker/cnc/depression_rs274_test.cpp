// Depression programs in every dialect, fitting and letter variant, interpreted by LinuxCNC's
// rs274: the program must run to the end, every engraving move must lie on a stroke, every
// stroke must be cut at full depth, and no rapid may move sideways below the surface.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "fonts/stroke_join.hpp"
#include "marker/cnc/depression.hpp"
#include "marker/cnc/gcode_writer.hpp"
#include "cnc_checks.hpp"
#include "rs274.hpp"
#include "test_figures.hpp"

namespace mark::test {
namespace {


class DepressionRs274 : public ::testing::TestWithParam<Case> {};

TEST_P(DepressionRs274, RunsToTheEndAndCutsExactlyTheStrokes) {
  REQUIRE_RS274();
  const auto [dialect, fit, variant] = GetParam();
  FigureSpec spec;
  spec.text = "DOLTSE";
  spec.fit = fit;
  spec.mirror = variant == Variant::mirrored;
  spec.italic_deg = variant == Variant::sheared ? 15 : 0;
  const Figure fig = make_figure(spec);

  CutSettings s;
  s.tool_diameter_mm = 0.5;
  s.depth_mm = 0.3;
  s.depth_per_pass_mm = 0.1;  // three passes: back and forth on open strokes
  const Toolpath tp = depression_toolpath(fig, s);
  GcodeOptions o;
  o.dialect = dialect;
  o.title = "depression test";
  o.header = {"(user header)"};
  o.footer = {"(user footer)"};
  GcodeStats stats;
  const std::string program = write_gcode(tp, o, &stats);
  const std::string file = std::string("depression_") + name(dialect) + "_" + name(fit) + "_" + name(variant);
  const Rs274Run run = run_rs274(program, file);
  ASSERT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;

  const DepressionCheck c = check_depression(fig, run, s, 0.0001);
  EXPECT_GT(c.arcs, 0u) << "arcs must stay arcs";
  EXPECT_LE(stats.max_arc_radius_error_mm, 0.005);
  // Every stroke of the six letters (strokes ordered across letters) is one subprogram call in
  // linuxcnc, a call when unrotated in fanuc, inlined in plain.
  std::size_t strokes = 0;
  for (const PlacedGlyph& g : fig.glyphs) strokes += chain_strokes(g.elements, fig.join_tolerance_mm()).size();
  EXPECT_GE(strokes, 6u);
  if (dialect == Dialect::linuxcnc) {
    EXPECT_EQ(stats.calls, strokes);
  } else if (dialect == Dialect::plain) {
    EXPECT_EQ(stats.calls, 0u);
    EXPECT_EQ(stats.inlined, strokes);
  } else {
    EXPECT_EQ(stats.calls + stats.inlined, strokes);
    if (fit == Fit::linear) {
      EXPECT_EQ(stats.calls, strokes);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllDialectsFitsVariants, DepressionRs274, all_cases(), case_name);

TEST(DepressionRs274, InchProgramCutsTheSameStrokes) {
  REQUIRE_RS274();
  FigureSpec spec;
  spec.fit = Fit::circular;
  spec.italic_deg = 10;
  const Figure fig = make_figure(spec);
  CutSettings s;
  s.depth_mm = 0.254;
  for (Dialect d : {Dialect::linuxcnc, Dialect::fanuc, Dialect::plain}) {
    GcodeOptions o;
    o.dialect = d;
    o.units = Units::inch;
    const std::string program = write_gcode(depression_toolpath(fig, s), o);
    EXPECT_NE(program.find("G20"), std::string::npos);
    const Rs274Run run = run_rs274(program, std::string("depression_inch_") + name(d));
    ASSERT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;
    // rs274 prints inches with 4 decimals: 0.00127 mm of print rounding.
    check_depression(fig, run, s, 0.0013);
  }
}

TEST(DepressionRs274, SinglePassWithEllipseChords) {
  REQUIRE_RS274();
  FigureSpec spec;
  spec.italic_deg = 20;
  const Figure fig = make_figure(spec);
  CutSettings s;
  s.arcs.ellipse_chords = true;
  GcodeStats stats;
  const std::string program = write_gcode(depression_toolpath(fig, s), GcodeOptions{}, &stats);
  const Rs274Run run = run_rs274(program, "depression_chords");
  ASSERT_EQ(run.exit_code, 0) << run.errors;
  const DepressionCheck c = check_depression(fig, run, s, 0.0001);
  EXPECT_EQ(c.arcs, 0u) << "sheared circles become chords when asked";
}

}  // namespace
}  // namespace mark::test
