// Protrusion programs interpreted by LinuxCNC's rs274, checked against the letters: the program
// runs to the end, no tool-centre position below the surface comes closer than the tool radius
// to a letter region, and no part of the plate wider than the tool is left standing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "base/error.hpp"
#include "cnc_checks.hpp"
#include "marker/cnc/gcode_writer.hpp"
#include "marker/cnc/protrusion.hpp"
#include "marker/geometry/clipper_paths.hpp"
#include "rs274.hpp"
#include "test_figures.hpp"

namespace mark::test {
namespace {

using ClipperLib::Paths;

class ProtrusionRs274 : public ::testing::TestWithParam<Case> {};

TEST_P(ProtrusionRs274, KeepsTheLettersAndClearsThePlate) {
  REQUIRE_RS274();
  const auto [dialect, fit, variant] = GetParam();
  FigureSpec spec;
  spec.text = "DOTS";
  spec.fit = fit;
  spec.gap_mm = 1.5;
  spec.mirror = variant == Variant::mirrored;
  spec.italic_deg = variant == Variant::sheared ? 15 : 0;
  const Figure fig = make_figure(spec);
  CutSettings s;
  s.tool_diameter_mm = 0.8;
  s.depth_mm = 0.4;
  // Two passes in one fitting per dialect; one elsewhere keeps the suite fast.
  s.depth_per_pass_mm = fit == Fit::circular && variant == Variant::upright ? 0.2 : 0;
  const ProtrusionResult res = protrusion_toolpath(fig, s, {});
  GcodeOptions o;
  o.dialect = dialect;
  const std::string program = write_gcode(res.toolpath, o);
  const Rs274Run run =
      run_rs274(program, std::string("protrusion_") + name(dialect) + "_" + name(fit) + "_" + name(variant));
  ASSERT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;
  const ProtrusionCheck c = check_protrusion(fig, run, s, res);
  EXPECT_GE(c.closest_to_letters_mm, s.tool_diameter_mm / 2 - kClosenessTolMm);
  EXPECT_EQ(c.wider_than_tool, 0);
  // The plate really is cleared: what stays is slivers in the letters' inside corners.
  EXPECT_LT(c.uncut_mm2, 0.02 * area_mm2(difference({rectangle_nm(res.plate)}, res.letters)));
  double deepest = 0;
  for (const CanonMove& m : run.moves) deepest = std::min(deepest, m.end.z());
  EXPECT_NEAR(deepest, -s.depth_mm, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(AllDialectsFitsVariants, ProtrusionRs274, all_cases(), case_name);

TEST(Protrusion, ReportsGapsNarrowerThanTheToolInsteadOfGouging) {
  REQUIRE_RS274();
  FigureSpec spec;
  spec.text = "LL";
  spec.gap_mm = 0.2;  // the L's foot ends 0.2 + 0.4 mm before the next L: narrower than the tool
  const Figure fig = make_figure(spec);
  CutSettings s;
  s.tool_diameter_mm = 1.0;
  ProtrusionSettings ps;
  ps.stroke_width_mm = 0.5;
  const ProtrusionResult res = protrusion_toolpath(fig, s, ps);
  ASSERT_FALSE(res.uncut.empty());
  double largest = 0;
  for (const UncutRegion& u : res.uncut) largest = std::max(largest, u.area_mm2);
  EXPECT_GT(largest, 0.1);  // the gap between the L's upright and the previous foot
  const Rs274Run run = run_rs274(write_gcode(res.toolpath, {}), "protrusion_narrow_gap");
  ASSERT_EQ(run.exit_code, 0) << run.errors;
  const ProtrusionCheck c = check_protrusion(fig, run, s, res);
  EXPECT_GE(c.closest_to_letters_mm, 0.5 - kClosenessTolMm);
  EXPECT_EQ(c.wider_than_tool, 0);
  // The report names what the interpreter's program really leaves standing (the grid counts
  // the film the keep-out slack leaves along the walls too: up to h × the letters' outline).
  double reported = 0;
  for (const UncutRegion& u : res.uncut) reported += u.area_mm2;
  EXPECT_NEAR(c.uncut_mm2, reported, 0.1);
}

TEST(Protrusion, RejectsAStepOverLargerThanTheToolRadius) {
  CutSettings s;
  s.tool_diameter_mm = 1;
  ProtrusionSettings ps;
  ps.stepover_mm = 0.6;
  EXPECT_THROW(protrusion_toolpath(make_figure({}), s, ps), InputError);
}


// --cutter-comp: the walls go out as part contours under G41 and the control offsets them. The
// interpreter's output is the compensated tool centre, so the same checks apply unchanged.
TEST(Protrusion, CutterCompensationByTheControl) {
  REQUIRE_RS274();
  FigureSpec spec;
  spec.text = "DOL";
  spec.gap_mm = 2.5;
  const Figure fig = make_figure(spec);
  CutSettings s;
  s.tool_diameter_mm = 0.8;
  s.depth_mm = 0.3;
  ProtrusionSettings ps;
  ps.cutter_comp = true;
  const ProtrusionResult res = protrusion_toolpath(fig, s, ps);
  // The plate's boundary and the outsides of D, O and L go to the control; the small counters
  // of D and O leave no room for a lead move and keep their tool-centre loops.
  EXPECT_GE(res.comp_walls, 4u);
  EXPECT_LE(res.walls_without_comp, 2u);
  for (Dialect d : {Dialect::linuxcnc, Dialect::fanuc}) {
    GcodeOptions o;
    o.dialect = d;
    const std::string program = write_gcode(res.toolpath, o);
    if (d == Dialect::linuxcnc) {
      EXPECT_NE(program.find("G41.1 D0.8 "), std::string::npos);
    } else {
      EXPECT_NE(program.find("G41 D1 "), std::string::npos);
      EXPECT_NE(program.find("(D1 = TOOL RADIUS 0.4 MM FOR G41)"), std::string::npos);
    }
    EXPECT_NE(program.find("G40 G1"), std::string::npos);
    // Fanuc's D1 is looked up in the tool table: tool 1, 0.8 mm = 0.031496 inch.
    const Rs274Run run = run_rs274(program, std::string("protrusion_comp_") + name(d), "T1 P1 D0.031496");
    ASSERT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;
    const ProtrusionCheck c = check_protrusion(fig, run, s, res);
    EXPECT_GE(c.closest_to_letters_mm, s.tool_diameter_mm / 2 - kClosenessTolMm);
    EXPECT_EQ(c.wider_than_tool, 0);
  }
  GcodeOptions plain;
  plain.dialect = Dialect::plain;
  EXPECT_THROW(write_gcode(res.toolpath, plain), InputError);
}

}  // namespace
}  // namespace mark::test
