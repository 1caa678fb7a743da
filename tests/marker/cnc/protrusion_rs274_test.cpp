// Protrusion programs interpreted by LinuxCNC's rs274, checked against the letters: the program
// runs to the end, no tool-centre position below the surface comes closer than the tool radius
// to a letter region, and no part of the plate wider than the tool is left standing.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>

#include "fonts/error.hpp"
#include "marker/cnc/clipper_paths.hpp"
#include "marker/cnc/gcode_writer.hpp"
#include "marker/cnc/protrusion.hpp"
#include "path_checks.hpp"
#include "rs274.hpp"
#include "test_figures.hpp"

namespace mark::test {
namespace {

using ClipperLib::Paths;

// The strokes are flattened for fast distance queries: distances are overstated by at most this.
constexpr double kStrokeChordMm = 0.0002;
// What "closer than the tool radius" forgives: the flattening above plus rs274's printout.
constexpr double kClosenessTolMm = kStrokeChordMm + 0.0002;

struct ProtrusionCheck {
  double closest_to_letters_mm = 1e9;  // smallest distance of a tool-centre position from L
  double uncut_mm2 = 0;                // material left inside the plate, outside the letters
  int wider_than_tool = 0;             // places where a whole tool disc of material is left
};

// Checks on a grid of points over the plate (spacing h): a point is cut when a full-depth move
// passes within the tool radius; an uncut point whose distance from every move is at least
// r + ρ, from the letters at least ρ and from the plate edge at least ρ is the centre of a
// disc of radius ρ left standing. With ρ = 0.95 r and h ≤ 0.07 r every leftover region that
// holds a whole tool disc contains such a grid point.
ProtrusionCheck check_protrusion(const Figure& fig, const Rs274Run& run, const CutSettings& s,
                                 const ProtrusionResult& res) {
  ProtrusionCheck c;
  const double r = s.tool_diameter_mm / 2, half_w = res.stroke_width_mm / 2;
  const SegmentGrid strokes = stroke_grid(fig, res.plate, kStrokeChordMm);
  // Distance from the letter region = distance from the strokes − half the stroke width.
  for (const CanonMove& m : run.moves) {
    if (m.start.z() >= 0 && m.end.z() >= 0) continue;
    const double near = half_w + r + 0.1;  // farther is clearly fine
    for (const Point& p : samples(m.path(), 0.02))
      c.closest_to_letters_mm = std::min(c.closest_to_letters_mm, strokes.distance(p, near) - half_w);
  }
  SegmentGrid cuts(res.plate, 0.25);
  for (const CanonMove& m : run.moves) {
    if (std::abs(m.end.z() + s.depth_mm) > 1e-3 || std::abs(m.start.z() + s.depth_mm) > 1e-3) continue;
    if (m.kind != CanonMove::arc) {
      cuts.add(m.start.head<2>(), m.end.head<2>());
      continue;
    }
    const std::vector<Point> pts = samples(m.path(), 0.02);  // chords 0.1 µm inside the arc
    for (std::size_t k = 1; k < pts.size(); ++k) cuts.add(pts[k - 1], pts[k]);
  }
  const double rho = 0.95 * r, h = std::min(0.02, 0.07 * r);
  for (double x = res.plate.min.x() + h / 2; x < res.plate.max.x(); x += h)
    for (double y = res.plate.min.y() + h / 2; y < res.plate.max.y(); y += h) {
      const Point p(x, y);
      if (cuts.any_within(p, r)) continue;
      const double d_cut = cuts.distance(p, r + rho);
      const double d_letters = strokes.distance(p, half_w + rho) - half_w;
      if (d_letters <= 0) continue;
      c.uncut_mm2 += h * h;
      const double d_edge = std::min({x - res.plate.min.x(), res.plate.max.x() - x,
                                      y - res.plate.min.y(), res.plate.max.y() - y});
      if (d_cut >= r + rho && d_letters >= rho && d_edge >= rho) ++c.wider_than_tool;
    }
  return c;
}

enum class Variant { upright, mirrored, sheared };
const char* name(Dialect d) { return d == Dialect::linuxcnc ? "linuxcnc" : d == Dialect::fanuc ? "fanuc" : "plain"; }
const char* name(Fit f) { return f == Fit::linear ? "linear" : f == Fit::inclined ? "inclined" : "circular"; }
const char* name(Variant v) { return v == Variant::upright ? "upright" : v == Variant::mirrored ? "mirrored" : "sheared"; }

using Case = std::tuple<Dialect, Fit, Variant>;
class ProtrusionRs274 : public ::testing::TestWithParam<Case> {};

TEST_P(ProtrusionRs274, KeepsTheLettersAndClearsThePlate) {
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

INSTANTIATE_TEST_SUITE_P(
    AllDialectsFitsVariants, ProtrusionRs274,
    ::testing::Combine(::testing::Values(Dialect::linuxcnc, Dialect::fanuc, Dialect::plain),
                       ::testing::Values(Fit::linear, Fit::inclined, Fit::circular),
                       ::testing::Values(Variant::upright, Variant::mirrored, Variant::sheared)),
    [](const ::testing::TestParamInfo<Case>& info) {
      return std::string(name(std::get<0>(info.param))) + "_" + name(std::get<1>(info.param)) + "_" +
             name(std::get<2>(info.param));
    });

TEST(Protrusion, ReportsGapsNarrowerThanTheToolInsteadOfGouging) {
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

}  // namespace
}  // namespace mark::test

namespace mark::test {
namespace {

// --cutter-comp: the walls go out as part contours under G41 and the control offsets them. The
// interpreter's output is the compensated tool centre, so the same checks apply unchanged.
TEST(Protrusion, CutterCompensationByTheControl) {
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
