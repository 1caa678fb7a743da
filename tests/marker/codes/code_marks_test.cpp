// A code's modules as marks, checked geometrically: every mark lies in a module meant to be
// marked (a dark one, or for an inverted code a light one or the quiet zone), each of those
// gets marks, lines end a beam radius inside their runs, dots are exact arcs, sizes and quiet
// zones come out as asked, and impossible layouts are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "base/error.hpp"
#include "marker/codes/code_marks.hpp"
#include "marker/codes/code_spec.hpp"

namespace mark {
namespace {

ModuleMatrix encoded(Symbology s, const std::string& data) {
  CodeSpec spec;
  spec.symbology = s;
  spec.data = data;
  return encode_code(spec);
}

// The module (row, col) of a code-frame point, and whether it is meant to be marked.
bool meant_marked(const PlacedCode& c, const Point& local) {
  const int col = static_cast<int>(std::floor(local.x() / c.module_mm));
  const int row = is_linear(c.matrix.symbology) ? 0 : static_cast<int>(std::floor((c.height_mm - local.y()) / c.module_mm));
  const bool inside = row >= 0 && row < c.matrix.rows && col >= 0 && col < c.matrix.cols;
  return (inside && c.matrix.dark(row, col)) != c.layout.invert;
}

// Every lit element, sampled, lies in modules meant to be marked; returns the marked modules hit.
std::set<std::pair<int, int>> check_marks_in_place(const PlacedCode& c) {
  const Affine to_local = c.to_field.inverse();
  std::set<std::pair<int, int>> hit;
  for (const Element& e : c.elements) {
    if (!e.laser()) continue;
    for (int k = 0; k <= 16; ++k) {
      const Point p = to_local * e.point_at(k / 16.0);
      EXPECT_TRUE(meant_marked(c, p)) << "mark at " << p.transpose() << " in a module meant bare";
      hit.insert({static_cast<int>(std::floor((c.height_mm - p.y()) / c.module_mm)),
                  static_cast<int>(std::floor(p.x() / c.module_mm))});
    }
  }
  return hit;
}

TEST(CodeMarks, SquareModulesAreHatchedInsideTheDarkModulesOnly) {
  const ModuleMatrix m = encoded(Symbology::datamatrix, "SN 0042");
  CodeLayout l;
  l.module_mm = 0.3;
  l.center = Point(5, -3);
  l.angle_deg = 30;
  const PlacedCode c = place_code(m, l);
  EXPECT_EQ(check_marks_in_place(c).size(), m.dark_count());
  // 0.3 mm modules at the default 0.035 mm spacing: fitted to 0.3 / 9, nine lines through every
  // module row of every run.
  std::size_t runs = 0;
  for (int r = 0; r < m.rows; ++r)
    for (int col = 0; col < m.cols; ++col) runs += m.dark(r, col) && (col == 0 || !m.dark(r, col - 1));
  EXPECT_EQ(c.stats.hatch_lines, 9 * runs);
  // Lines end a beam radius inside their run: total length = Σ (run length − 2 r) per line.
  double expected = 0;
  for (int r = 0; r < m.rows; ++r)
    for (int col = 0; col < m.cols;) {
      if (!m.dark(r, col)) {
        ++col;
        continue;
      }
      int e = col;
      while (e < m.cols && m.dark(r, e)) ++e;
      expected += 9 * ((e - col) * 0.3 - 2 * 0.02);
      col = e;
    }
  EXPECT_NEAR(c.stats.hatch_length_mm, expected, 1e-9);
}

TEST(CodeMarks, SizeGivesTheModuleAndTheQuietZoneSurroundsTheSymbol) {
  const ModuleMatrix m = encoded(Symbology::datamatrix, "HELLO 123");  // 14 × 14
  CodeLayout l;
  l.size_mm = 7;
  const PlacedCode c = place_code(m, l);
  EXPECT_DOUBLE_EQ(c.module_mm, 0.5);
  EXPECT_EQ(c.quiet_modules, 1);
  EXPECT_NEAR(c.bounds.width(), 7 + 2 * 0.5, 1e-9);
  EXPECT_NEAR(c.bounds.center().x(), 0, 1e-9);
  const PlacedCode qr = place_code(encoded(Symbology::qr, "ABC"), CodeLayout{});
  EXPECT_EQ(qr.quiet_modules, 4);
  EXPECT_NEAR(qr.bounds.width(), (21 + 8) * kDefaultModule_mm, 1e-9);
  // A linear code's quiet zone is left and right of its bars.
  const PlacedCode bars = place_code(encoded(Symbology::code128, "A1"), CodeLayout{});
  EXPECT_NEAR(bars.bounds.width(), (bars.matrix.cols + 20) * kDefaultModule_mm, 1e-9);
  EXPECT_NEAR(bars.bounds.height(), bars.height_mm, 1e-9);
  EXPECT_NEAR(bars.height_mm, 0.15 * bars.width_mm, 1e-9);
}

TEST(CodeMarks, InvertedCodeMarksTheLightModulesAndTheQuietZone) {
  const ModuleMatrix m = encoded(Symbology::datamatrix, "SN 0042");
  CodeLayout l;
  l.invert = true;
  const PlacedCode c = place_code(m, l);
  const std::size_t light_and_quiet = m.modules.size() - m.dark_count() + 4 * (m.rows + 1);
  EXPECT_EQ(check_marks_in_place(c).size(), light_and_quiet);
}

TEST(CodeMarks, DotsAreExactArcsAndSpiralsFillTheirDisc) {
  const ModuleMatrix m = encoded(Symbology::datamatrix, "SN 0042");
  CodeLayout l;
  l.module_mm = 0.4;
  l.style = ModuleStyle::dot;
  l.dot = DotShape::circle;
  const PlacedCode circles = place_code(m, l);
  std::size_t n = 0;
  for (const Element& e : circles.elements)
    if (e.laser()) {
      ASSERT_EQ(e.kind(), ElementKind::arc);
      EXPECT_NEAR(std::get<CircularArc>(e.geometry()).radius, 0.2 - 0.02, 1e-12);
      ++n;
    }
  EXPECT_EQ(n, m.dark_count());
  check_marks_in_place(circles);
  l.dot = DotShape::spiral;
  const PlacedCode spirals = place_code(m, l);
  check_marks_in_place(spirals);
  // Per dot: radius 0.18 at pitch ≤ 0.035 → k = 2·⌈0.18 / 0.035⌉ = 12 half turns: 11
  // semicircles and the circle.
  EXPECT_EQ(spirals.stats.hatch_lines, 12 * m.dark_count());
  for (std::size_t k = 1; k < spirals.elements.size(); ++k)
    EXPECT_LT((spirals.elements[k].start() - spirals.elements[k - 1].end()).norm(), 1e-9);
}

TEST(CodeMarks, LineStyleCoversEachModuleRowWithLinesAtMostTheSpacingApart) {
  const ModuleMatrix m = encoded(Symbology::datamatrix, "SN 0042");
  std::size_t runs = 0;
  for (int r = 0; r < m.rows; ++r)
    for (int col = 0; col < m.cols; ++col) runs += m.dark(r, col) && (col == 0 || !m.dark(r, col - 1));
  CodeLayout l;
  l.style = ModuleStyle::line;
  // Beam radius r = 0.02, hatch spacing 0.035 mm: line centres from r to module − r, at most the
  // spacing apart. A 0.04 mm module takes one line in its middle, 0.05 mm two (at 0.02 and 0.03),
  // 0.3 mm 1 + ⌈0.26 / 0.035⌉ = 9.
  for (const auto& [module_mm, per_module] : {std::pair{0.04, 1}, {0.05, 2}, {0.3, 9}}) {
    SCOPED_TRACE(module_mm);
    l.module_mm = module_mm;
    const PlacedCode c = place_code(m, l);
    EXPECT_EQ(c.stats.hatch_lines, runs * per_module);
    check_marks_in_place(c);
    std::set<long> offsets_nm;  // line centres across their module row, from its top edge
    for (const Element& e : c.elements)
      if (e.laser()) {
        const double down = c.height_mm - (c.to_field.inverse() * e.start()).y();
        offsets_nm.insert(std::lround(std::fmod(down + 1e-9, module_mm) * 1e6));
      }
    ASSERT_EQ(offsets_nm.size(), static_cast<std::size_t>(per_module));
    if (per_module == 1) {
      EXPECT_NEAR(*offsets_nm.begin(), module_mm / 2 * 1e6, 2);
    } else {
      EXPECT_NEAR(*offsets_nm.begin(), 0.02 * 1e6, 2);
      EXPECT_NEAR(*offsets_nm.rbegin(), (module_mm - 0.02) * 1e6, 2);
      const double pitch_nm = (module_mm - 0.04) * 1e6 / (per_module - 1);
      EXPECT_LE(pitch_nm, 35000 + 1);
    }
  }
}

TEST(CodeMarks, ImpossibleLayoutsAreRefused) {
  const ModuleMatrix m = encoded(Symbology::datamatrix, "SN 0042");
  const auto error = [&](CodeLayout l) {
    try {
      place_code(m, l);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CodeLayout l;
  l.module_mm = 0.04;  // no wider than the 40 µm beam
  EXPECT_NE(error(l).find("square modules would vanish"), std::string::npos);
  l.style = ModuleStyle::dot;
  EXPECT_NE(error(l).find("too small for dots"), std::string::npos);
  l = CodeLayout{};
  l.module_mm = 0.3;
  l.size_mm = 4;
  EXPECT_EQ(error(l), "give the module size or the code size, not both");
  l = CodeLayout{};
  l.module_mm = 50;
  EXPECT_EQ(error(l), "module size: 50 is outside the range 0.01 to 20 mm");
  l = CodeLayout{};
  l.angle_deg = NAN;
  EXPECT_EQ(error(l), "code angle: nan is outside the range -360 to 360 degrees");
  l = CodeLayout{};
  l.style = ModuleStyle::dot;
  try {
    place_code(encoded(Symbology::code128, "A"), l);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dot style is for 2-D codes"), std::string::npos);
  }
}

}  // namespace
}  // namespace mark
