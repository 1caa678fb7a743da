// V-carving against references we did not write: the closed-form medial axis of a bar and of a
// ring (position and depth), the exact outline of real TrueType letters (the cone never crosses
// it), LinuxCNC's rs274 (every program runs, in every dialect and unit), and F-Engrave 1.75's
// V-carve of the same letters (a committed fixture, see data/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "fonts/catalog.hpp"
#include "fonts/error.hpp"
#include "marker/cnc/element_distance.hpp"
#include "marker/cnc/gcode_writer.hpp"
#include "marker/cnc/vcarve.hpp"
#include "marker/layout/layout.hpp"
#include "path_checks.hpp"
#include "rs274.hpp"

namespace mark::test {
namespace {

constexpr double kPrintMm = 0.0001;  // rs274 prints 4 decimals in mm
const std::string kDejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

double tan_half(const VCarveSettings& v) { return std::tan(v.bit_angle_deg / 2 * std::numbers::pi / 180); }

// One letter made of the given closed contours, placed at the origin.
Figure letter_figure(std::vector<Element> elements, double height_mm) {
  Figure f;
  ShapedGlyph shape;
  shape.code_point = U'X';
  shape.elements = elements;
  shape.advance_mm = 1;
  f.shapes.push_back(shape);
  PlacedGlyph g;
  g.code_point = U'X';
  g.elements = std::move(elements);
  f.glyphs.push_back(std::move(g));
  f.letter_height_mm = height_mm;
  return f;
}

std::vector<Element> rectangle(double w, double h) {
  return {Element::line({0, 0}, {w, 0}), Element::line({w, 0}, {w, h}), Element::line({w, h}, {0, h}),
          Element::line({0, h}, {0, 0})};
}

// The cutting moves of an interpreted program, in mm: feeds that move sideways with either end
// below the surface (a V-carve path runs up to the surface at the letter's corners).
std::vector<CanonMove> carving_moves(const Rs274Run& run) {
  std::vector<CanonMove> cuts;
  for (const CanonMove& m : run.moves)
    if (m.kind != CanonMove::traverse && (m.start.z() < 0 || m.end.z() < 0) &&
        (m.end.head<2>() - m.start.head<2>()).norm() > 0)
      cuts.push_back(m);
  return cuts;
}

// The program (linuxcnc, mm) through rs274, its carving moves back.
std::vector<CanonMove> interpreted_cuts(const Toolpath& tp, const std::string& name) {
  const Rs274Run run = run_rs274(write_gcode(tp, GcodeOptions{}), name);
  EXPECT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;
  return carving_moves(run);
}

// Points along every interpreted cutting move, with the depth interpolated as the machine moves.
struct CutPoint {
  Point p;
  double z;
};
std::vector<CutPoint> along(const std::vector<CanonMove>& cuts, double step_mm) {
  std::vector<CutPoint> out;
  for (const CanonMove& m : cuts) {
    const double len = (m.end.head<2>() - m.start.head<2>()).norm();
    const int n = std::max(1, static_cast<int>(std::ceil(len / step_mm)));
    for (int k = 0; k <= n; ++k) {
      const Eigen::Vector3d q = m.start + (m.end - m.start) * (static_cast<double>(k) / n);
      out.push_back({q.head<2>(), q.z()});
    }
  }
  return out;
}

double distance_to_segment_set(const Point& p, const std::vector<std::pair<Point, Point>>& segs) {
  double d = 1e9;
  for (const auto& [a, b] : segs) d = std::min(d, distance_to_segment(p, a, b));
  return d;
}

TEST(VCarve, BarFollowsItsClosedFormMedialAxisInXyAndDepth) {
  const double w = 10, h = 2;
  const Figure fig = letter_figure(rectangle(w, h), h);
  CutSettings cut;
  cut.tool_diameter_mm = 10;  // the bit's diameter limits nothing here
  VCarveSettings v;
  const VCarveResult r = vcarve_toolpath(fig, cut, v);
  // A w × h bar (h < w): the centre line from (h/2, h/2) to (w − h/2, h/2) and the four corner
  // bisectors; the depth at p is its distance to the outline over tan(half angle).
  const std::vector<std::pair<Point, Point>> axis = {{{h / 2, h / 2}, {w - h / 2, h / 2}},
                                                     {{0, 0}, {h / 2, h / 2}},
                                                     {{0, h}, {h / 2, h / 2}},
                                                     {{w, 0}, {w - h / 2, h / 2}},
                                                     {{w, h}, {w - h / 2, h / 2}}};
  const double t = tan_half(v);
  const std::vector<CutPoint> pts = along(interpreted_cuts(r.toolpath, "vcarve_bar"), 0.05);
  ASSERT_GT(pts.size(), 100u);
  double worst_xy = 0, worst_z = 0;
  for (const CutPoint& c : pts) {
    worst_xy = std::max(worst_xy, distance_to_segment_set(c.p, axis));
    const double outline = std::min({c.p.x(), w - c.p.x(), c.p.y(), h - c.p.y()});
    worst_z = std::max(worst_z, std::abs(-c.z - outline / t));
  }
  // A bar has only straight sides: no flattening, radius linear along every axis edge.
  EXPECT_LE(worst_xy, kPrintMm);
  EXPECT_LE(worst_z, (v.tolerance_mm + kPrintMm) / t);
  // Every point of the true axis is cut.
  for (const auto& [a, b] : axis)
    for (int k = 0; k <= 50; ++k) {
      const Point q = a + (b - a) * (k / 50.0);
      double nearest = 1e9;
      for (const CutPoint& c : pts) nearest = std::min(nearest, (c.p - q).norm());
      EXPECT_LE(nearest, 0.05) << "axis point (" << q.x() << ", " << q.y() << ") not cut";
    }
  EXPECT_NEAR(r.deepest_mm, h / 2 / t, v.tolerance_mm / t);
  EXPECT_EQ(r.flat_area_mm2, 0);
}

TEST(VCarve, RingCarvesItsMidCircleAtHalfTheWidth) {
  const double r1 = 3, r2 = 5;
  // Outer boundary counter-clockwise, the hole clockwise: under the non-zero rule a ring.
  const Figure fig =
      letter_figure({Element::arc({0, 0}, r2, 0, 2 * std::numbers::pi), Element::line({r2, 0}, {r1, 0}, false),
                     Element::arc({0, 0}, r1, 0, -2 * std::numbers::pi)},
                    2 * r2);
  CutSettings cut;
  cut.tool_diameter_mm = 10;
  VCarveSettings v;
  const VCarveResult r = vcarve_toolpath(fig, cut, v);
  const double t = tan_half(v), mid = (r1 + r2) / 2, half_width = (r2 - r1) / 2;
  const std::vector<CutPoint> pts = along(interpreted_cuts(r.toolpath, "vcarve_ring"), 0.05);
  ASSERT_GT(pts.size(), 100u);
  double worst_xy = 0, worst_z = 0;
  for (const CutPoint& c : pts) {
    worst_xy = std::max(worst_xy, std::abs(c.p.norm() - mid));
    worst_z = std::max(worst_z, std::abs(-c.z - half_width / t));
  }
  // Within the tolerance of the mid circle — so the branches to every chord corner of the
  // flattened circles were pruned — and the depth within the tolerance's share of it.
  EXPECT_LE(worst_xy, v.tolerance_mm + kPrintMm);
  EXPECT_LE(worst_z, (v.tolerance_mm + kPrintMm) / t);
  // Never deeper than the exact depth: the radius is reduced by what flattening may add.
  for (const CutPoint& c : pts) EXPECT_LE(-c.z, half_width / t + kPrintMm);
  // The whole mid circle is cut.
  for (int k = 0; k < 360; ++k) {
    const Point q = mid * Point(std::cos(k * std::numbers::pi / 180), std::sin(k * std::numbers::pi / 180));
    double nearest = 1e9;
    for (const CutPoint& c : pts) nearest = std::min(nearest, (c.p - q).norm());
    ASSERT_LE(nearest, 0.05) << "mid circle at " << k << "° not cut";
  }
  EXPECT_GT(r.pruned_edges, 0u);
}

// Every point of every cut of real letters: the cone's radius at the surface (depth · tan) is
// no larger than the distance to the exact outline (lines and biarc arcs of the font).
TEST(VCarve, TheConeNeverCrossesTheOutlineOfRealLetters) {
  const auto font = open_font(kDejaVu, nullptr);
  LayoutOptions o;
  o.height_mm = 10;
  const Figure fig = layout_text("Ag&8", *font, o);
  CutSettings cut;
  cut.tool_diameter_mm = 10;
  VCarveSettings v;
  const VCarveResult r = vcarve_toolpath(fig, cut, v);
  NearSet outline;
  for (const PlacedGlyph& g : fig.glyphs)
    for (const Element& e : g.elements)
      if (e.laser()) outline.add(e);
  const double t = tan_half(v);
  double worst = -1e9, closest_miss = 1e9;
  for (const CutPoint& c : along(interpreted_cuts(r.toolpath, "vcarve_letters"), 0.02)) {
    const double reach = -c.z * t;
    const double d = outline.distance(c.p, 10);
    worst = std::max(worst, reach - d);
    closest_miss = std::min(closest_miss, d - reach);
  }
  EXPECT_LE(worst, kPrintMm * (1 + t));  // the printout's rounding of x, y and z
  // …and it reaches the outline where it should: the carve is not simply shallow.
  EXPECT_LE(closest_miss, v.tolerance_mm);
}

TEST(VCarve, NeverDeeperThanMaxDepthAndTheFlatBottomIsCleared) {
  const double w = 12, h = 4;
  const Figure fig = letter_figure(rectangle(w, h), h);
  CutSettings cut;
  cut.tool_diameter_mm = 10;
  VCarveSettings v;
  v.max_depth_mm = 0.8;
  v.flat_bottom_mm = 1;
  const VCarveResult r = vcarve_toolpath(fig, cut, v);
  const double t = tan_half(v), r_cap = v.max_depth_mm * t;
  EXPECT_DOUBLE_EQ(r.depth_limit_mm, v.max_depth_mm);
  // The flat bottom: the bar inset by the cap's radius, and by up to the tolerance more (what
  // Clipper's round joins and the margin take, so the V-bit round it never reaches the outline).
  EXPECT_LE(r.flat_area_mm2, (w - 2 * r_cap) * (h - 2 * r_cap));
  EXPECT_GE(r.flat_area_mm2, (w - 2 * r_cap - 2 * v.tolerance_mm) * (h - 2 * r_cap - 2 * v.tolerance_mm));
  const std::vector<CutPoint> carve = along(interpreted_cuts(r.toolpath, "vcarve_capped"), 0.05);
  double deepest = 0;
  for (const CutPoint& c : carve) deepest = std::max(deepest, -c.z);
  EXPECT_LE(deepest, v.max_depth_mm + kPrintMm);
  EXPECT_GE(deepest, v.max_depth_mm - kPrintMm);
  // The end mill: only at the cap's depth on its last pass, its disc always inside the flat
  // bottom (never into the V walls), and it reaches all of the flat bottom but its corners.
  const std::vector<CutPoint> mill = along(interpreted_cuts(r.cleanup, "vcarve_cleanup"), 0.05);
  ASSERT_FALSE(mill.empty());
  for (const CutPoint& c : mill) {
    EXPECT_GE(-c.z, 0);
    EXPECT_LE(-c.z, v.max_depth_mm + kPrintMm);
    const double to_outline = std::min({c.p.x(), w - c.p.x(), c.p.y(), h - c.p.y()});
    ASSERT_GE(to_outline, r_cap + v.flat_bottom_mm / 2 - kPrintMm) << "at (" << c.p.x() << ", " << c.p.y() << ")";
  }
  // Square corners stay for a 0.5 mm radius mill: 4 · (1 − π/4) · 0.5² mm², and at most a
  // tolerance-wide band along the flat bottom's edge (Clipper's polygons lie inside its arcs).
  const double corners = 4 * (1 - std::numbers::pi / 4) * 0.25;
  EXPECT_GE(r.uncleaned_area_mm2, corners - 0.001);
  EXPECT_LE(r.uncleaned_area_mm2, corners + 2 * (w + h) * v.tolerance_mm);
}

TEST(VCarve, OpenStrokesAreRefusedNamingTheLetter) {
  LayoutOptions o;
  o.height_mm = 5;
  const Figure fig = layout_text("AL", builtin_font(), o);
  try {
    vcarve_toolpath(fig, CutSettings{}, VCarveSettings{});
    FAIL() << "an open stroke was carved";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("v-carve: 'A' (U+0041) has an open stroke"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("closed outlines"), std::string::npos) << e.what();
  }
}

// Every dialect, both units, passes of at most 0.3 mm: rs274 runs each program to the end, the
// deepest cut is the carve's, and each path is cut once per pass (about three times as many
// cutting moves as in one pass for a letter about 0.8 mm deep).
TEST(VCarve, Rs274RunsEveryDialectAndUnitWithPasses) {
  const auto font = open_font(kDejaVu, nullptr);
  LayoutOptions o;
  o.height_mm = 8;
  o.angle_deg = 15;  // rotated letters: LinuxCNC rotates inside the subprogram, the others inline
  const Figure fig = layout_text("R8", *font, o);
  CutSettings cut;
  cut.tool_diameter_mm = 10;
  VCarveSettings v;
  const std::size_t one_pass = interpreted_cuts(vcarve_toolpath(fig, cut, v).toolpath, "vcarve_one_pass").size();
  cut.depth_per_pass_mm = 0.3;
  const VCarveResult r = vcarve_toolpath(fig, cut, v);
  const std::size_t passes = static_cast<std::size_t>(std::ceil(r.deepest_mm / 0.3 - 1e-9));
  ASSERT_GE(passes, 2u);
  for (Dialect d : {Dialect::linuxcnc, Dialect::fanuc, Dialect::plain})
    for (Units u : {Units::mm, Units::inch}) {
      GcodeOptions g;
      g.dialect = d;
      g.units = u;
      const std::string name = std::string("vcarve_passes_") +
                               (d == Dialect::linuxcnc ? "linuxcnc" : d == Dialect::fanuc ? "fanuc" : "plain") +
                               (u == Units::mm ? "_mm" : "_inch");
      const Rs274Run run = run_rs274(write_gcode(r.toolpath, g), name);
      ASSERT_EQ(run.exit_code, 0) << run.file << ":\n" << run.errors;
      const std::vector<CanonMove> cuts = carving_moves(run);
      double deepest = 0;
      for (const CanonMove& m : cuts) deepest = std::max(deepest, -m.end.z());
      // The inch printout has 4 decimals: 0.0025 mm.
      EXPECT_NEAR(deepest, r.deepest_mm, u == Units::mm ? kPrintMm : 0.0026) << name;
      EXPECT_GE(cuts.size(), (passes - 1) * one_pass) << name;
      EXPECT_LE(cuts.size(), (passes + 1) * one_pass) << name;
    }
}

// F-Engrave 1.75's V-carve of the same letters (data/README.md: same font, height, spacing and
// bit, no depth limit). Every point F-Engrave cuts below the surface lies on our carve within
// 5 µm in XY, at our depth there within 10 µm; and every point we cut lies within 10 µm of
// F-Engrave's path. Both programs are read by rs274.
TEST(VCarve, DepthAlongTheCentreLinesMatchesFEngrave) {
  const auto font = open_font(kDejaVu, nullptr);
  LayoutOptions o;
  o.height_mm = 10;
  const Figure fig = layout_text("Ag", *font, o);
  CutSettings cut;
  cut.tool_diameter_mm = 20;
  const VCarveResult r = vcarve_toolpath(fig, cut, VCarveSettings{});
  const std::vector<CanonMove> ours = interpreted_cuts(r.toolpath, "vcarve_Ag");
  const Rs274Run fe = run_rs274(slurp(std::string(MARKER_SOURCE_DIR) + "/tests/marker/cnc/data/fengrave_Ag_vcarve.ngc"),
                                "fengrave_Ag_vcarve");
  ASSERT_EQ(fe.exit_code, 0) << fe.errors;
  const std::vector<CanonMove> theirs = carving_moves(fe);
  ASSERT_GT(theirs.size(), 500u);

  // The nearest point of a set of 3D polyline moves in XY, and the depth there.
  const auto nearest = [](const std::vector<CanonMove>& moves, const Point& p) {
    double best = 1e9, z = 0;
    for (const CanonMove& m : moves) {
      const Point a = m.start.head<2>(), b = m.end.head<2>();
      const double len2 = (b - a).squaredNorm();
      const double t = len2 > 0 ? std::clamp((p - a).dot(b - a) / len2, 0.0, 1.0) : 0.0;
      const double d = (a + t * (b - a) - p).norm();
      if (d < best) best = d, z = m.start.z() + t * (m.end.z() - m.start.z());
    }
    return std::pair(best, z);
  };
  double worst_xy = 0, worst_z = 0;
  std::size_t compared = 0;
  for (const CanonMove& m : theirs)
    for (const Eigen::Vector3d& q : {m.start, m.end}) {
      if (q.z() >= 0) continue;
      const auto [d, z] = nearest(ours, q.head<2>());
      worst_xy = std::max(worst_xy, d);
      worst_z = std::max(worst_z, std::abs(z - q.z()));
      ++compared;
    }
  EXPECT_GT(compared, 800u);
  EXPECT_LE(worst_xy, 0.005);
  EXPECT_LE(worst_z, 0.010);
  double back_xy = 0;
  for (const CanonMove& m : ours)
    for (const Eigen::Vector3d& q : {m.start, m.end})
      if (q.z() < -0.01) back_xy = std::max(back_xy, nearest(theirs, q.head<2>()).first);
  EXPECT_LE(back_xy, 0.010);
}

}  // namespace
}  // namespace mark::test
