// The order strokes are cut in. The reference is F-Engrave 1.75's own ordering, written here
// from its source (f-engrave.py, Sort_Paths): consecutive segments of the text whose ends meet
// within its accuracy form a loop; from the first loop, the next is the one whose start or end
// is nearest to where the tool is. On the same layout our rapid travel must not be longer.
// And strokes are ordered across letters: a letter's strokes may be interleaved with its
// neighbours'.
#include <gtest/gtest.h>

#include <limits>

#include "fonts/catalog.hpp"
#include "marker/cnc/depression.hpp"
#include "marker/layout/layout.hpp"

namespace mark {
namespace {

const std::string kNormalCxf = std::string(MARKER_SOURCE_DIR) + "/tests/fonts/data/normal.cxf";

// F-Engrave's Sort_Paths on the figure's lit elements in text order: the rapid travel from the
// end of the first loop on.
double fengrave_travel(const Figure& fig, double accuracy_mm) {
  struct Loop {
    Point begin, end;
  };
  std::vector<Loop> loops;
  Point last(1e18, 1e18);
  for (const PlacedGlyph& g : fig.glyphs)
    for (const Element& e : g.elements) {
      if (!e.laser()) continue;
      if ((e.start() - last).norm() > accuracy_mm || loops.empty())
        loops.push_back({e.start(), e.end()});
      else
        loops.back().end = e.end();
      last = e.end();
    }
  std::vector<bool> used(loops.size(), false);
  used[0] = true;
  Point at = loops[0].end;
  double travel = 0;
  for (std::size_t round = 1; round < loops.size(); ++round) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t pick = 0;
    bool from_end = false;
    for (std::size_t k = 0; k < loops.size(); ++k) {
      if (used[k]) continue;
      const double b = (loops[k].begin - at).norm(), e = (loops[k].end - at).norm();
      if (b < best) best = b, pick = k, from_end = false;
      if (e < best) best = e, pick = k, from_end = true;
    }
    used[pick] = true;
    travel += best;
    at = from_end ? loops[pick].begin : loops[pick].end;
  }
  return travel;
}

TEST(DepressionOrder, RapidTravelIsNoLongerThanFEngravesOnTheSameLayout) {
  const auto font = open_font(kNormalCxf, nullptr);
  for (int rows : {1, 10, 40}) {
    std::string text;
    for (int k = 0; k < rows; ++k)
      text += (k ? "\n" : "") + std::string("The quick brown fox jumps over the lazy dog. 0123456789 ABCDEF");
    LayoutOptions o;
    o.height_mm = 1;
    const Figure fig = layout_text(text, *font, o);
    CutSettings s;
    s.tool_diameter_mm = 0.1;
    s.depth_mm = 0.1;
    const double ours = rapid_travel(depression_toolpath(fig, s)).xy_mm;
    // F-Engrave's accuracy default, 0.001 (in its units: mm here).
    const double theirs = fengrave_travel(fig, 0.001);
    EXPECT_LE(ours, theirs) << rows << " rows";
    RecordProperty("rapid_mm_" + std::to_string(rows) + "_rows", std::to_string(ours) + " vs " + std::to_string(theirs));
  }
}

TEST(DepressionOrder, StrokesAreInterleavedAcrossLettersWhereThatSavesTravel) {
  // Two letters, each a stroke on the left and one on the right, far apart: in text order the
  // tool would go left, right, back left, right; across letters it cuts both left strokes first.
  Figure fig;
  ShapedGlyph shape;
  shape.code_point = U'X';
  shape.elements = {Element::line({0, 0}, {0, 1}), Element::line({0, 1}, {20, 0}, false), Element::line({20, 0}, {20, 1})};
  shape.advance_mm = 1;
  fig.shapes.push_back(shape);
  for (double x : {0.0, 1.0}) {
    PlacedGlyph g;
    g.code_point = U'X';
    g.origin = Point(x, 0);
    for (const Element& e : shape.elements) g.elements.push_back(e.transformed(Affine(Eigen::Translation2d(x, 0))));
    fig.glyphs.push_back(g);
  }
  fig.letter_height_mm = 1;
  const Toolpath tp = depression_toolpath(fig, CutSettings{});
  ASSERT_EQ(tp.steps.size(), 4u);
  std::vector<double> xs;
  for (const ToolStep& st : tp.steps) {
    const auto& call = std::get<SubprogramCall>(st);
    xs.push_back(call.origin.x() + tp.subs[call.sub].body.front().end.x());
  }
  // Left strokes of both letters, then right strokes of both, each pair back and forth: 1 mm
  // across, 19 mm from (1, 0) to (20, 0), 1 mm across — the shortest tour. In text order it
  // would be 1 + 20 + 19 (and back) + 20 mm.
  EXPECT_LT(std::max(xs[0], xs[1]), 2.0);
  EXPECT_GT(std::min(xs[2], xs[3]), 19.0);
  EXPECT_NEAR(rapid_travel(tp).xy_mm, 1 + 19 + 1, 1e-9);
}

}  // namespace
}  // namespace mark
