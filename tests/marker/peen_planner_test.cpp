// The three planners: each strikes every dot once and only with legal gantry moves, on texts
// laid out every way; the block snake follows the patent's six steps on hand-worked matrices;
// the whole-window snake sweeps the whole window.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/error.hpp"
#include "marker/peen/block_snake.hpp"
#include "marker/peen/gantry_run.hpp"
#include "marker/peen/tour_planner.hpp"
#include "marker/peen/window_snake.hpp"
#include "peen_test_support.hpp"

namespace mark {
namespace {

using peen_test::expect_each_dot_once;
using peen_test::matrix_text;
using peen_test::struck_cells;

// Every move starts where the last one ended (from home, back to home), stands on whole steps
// inside the window, and each axis' profile is a real trapezoid within the axis' limits that
// covers exactly the axis' distance; the move lasts as long as its slower axis.
void expect_legal_moves(const PeenPlan& plan, const GantryConfig& g, const Box& window) {
  const GantryReport r = run_plan(plan, g, true);
  StepPoint at = to_steps(plan.home_mm, g);
  // A dot on the window's edge may round half a step outside it.
  const double half_step = 0.5 / std::min(g.x.steps_per_mm, g.y.steps_per_mm) * (1 + 1e-9);
  for (const GantryMove& m : r.log) {
    ASSERT_EQ(m.from, at) << plan.planner;
    at = m.to;
    const Point mm = to_mm(m.to, g);
    EXPECT_TRUE(window.contains(Box{mm, mm}, half_step))
        << plan.planner << " leaves the window at " << mm.transpose();
    for (const auto& [p, axis, steps] :
         {std::tuple{m.x, g.x, m.to.x - m.from.x}, std::tuple{m.y, g.y, m.to.y - m.from.y}}) {
      EXPECT_EQ(p.steps, steps);
      EXPECT_NEAR(p.distance_mm, std::abs(static_cast<double>(steps)) / axis.steps_per_mm, 1e-12);
      EXPECT_LE(p.peak_speed_mm_s, axis.max_speed_mm_s * (1 + 1e-12));
      if (p.accel_s > 0) {
        EXPECT_LE(p.peak_speed_mm_s / p.accel_s, axis.accel_mm_s2 * (1 + 1e-9));
      }
      // Area under the speed profile: two ramps of v·t/2 and the cruise.
      EXPECT_NEAR(p.peak_speed_mm_s * (p.accel_s + p.cruise_s), p.distance_mm, 1e-9);
    }
    EXPECT_DOUBLE_EQ(m.duration_s, std::max(m.x.duration_s(), m.y.duration_s()));
  }
  EXPECT_EQ(at, to_steps(plan.home_mm, g)) << plan.planner << " does not end at home";
}

void check_all_planners(const DotText& text, const std::string& what) {
  SCOPED_TRACE(what);
  const PeenSetup setup{tight_window(text), GantryConfig{}};
  for (PlannerKind k : kAllPlanners) {
    const PeenPlan plan = plan_peen(text, k, setup);
    EXPECT_EQ(plan.planner, planner_name(k));
    expect_each_dot_once(text, plan);
    expect_legal_moves(plan, setup.gantry, setup.window);
  }
}

TEST(PeenPlanners, EveryDotOnceWithLegalMovesWhateverTheLayout) {
  check_all_planners(peen_test::serial_5x7(), "5x7 serial");
  check_all_planners(peen_test::patent_eights(), "10x16 eights");
  LayoutOptions o;
  o.height_mm = 4;
  o.angle_deg = 17;
  check_all_planners(layout_dot_text("VIN 1HGCM82633A", dot_font_7x9(), o), "7x9 inclined");
  o.angle_deg = 0;
  o.mirror = true;
  o.italic_deg = 10;
  check_all_planners(layout_dot_text("MIRROR-42", dot_font_5x7(), o), "5x7 mirrored italic");
  o = LayoutOptions{};
  o.height_mm = 3;
  o.circle = CircleFit{{0, 0}, 15, std::nullopt, false};
  check_all_planners(layout_dot_text("ROUND #7", dot_font_5x7(), o), "5x7 circular");
  o.circle->inside = true;
  o.height_mm = 2;
  o.line_spacing = 1.2;
  check_all_planners(layout_dot_text("AB\nCD", dot_font_5x7(), o), "two lines inside a circle");
}

TEST(PeenPlanners, StrokeDotsWithSharedCellsAreStruckOnce) {
  FontMetrics m;
  m.cap_height = m.standard_height = 10;
  m.line_height = 14;
  StrokeFont f("strokes", "test", m);
  Glyph x;
  x.code_point = U'X';
  x.elements = {Element::line({0, 0}, {8, 10}), Element::line({0, 10}, {8, 0}),
                Element::arc({4, 5}, 3, 0, 6.0)};
  x.advance = 10;
  f.add(x);
  LayoutOptions o;
  o.height_mm = 6;
  o.angle_deg = 8;
  // A pitch that puts several dots in some cells and crossings closer than a pitch.
  const DotText t = dots_along_strokes(layout_text("XX", f, o), 0.37);
  EXPECT_EQ(t.characters, 2u);
  check_all_planners(t, "stroke dots");
}

TEST(PeenPlanners, EmptyTextAndDotsOutsideTheWindowAreRefused) {
  const DotText t = peen_test::serial_5x7();
  try {
    plan_peen(t, PlannerKind::block, PeenSetup{centred_window(20, 20), GantryConfig{}});
    FAIL() << "a 38 mm serial fits a 20 mm window";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("leave the marking window"), std::string::npos) << e.what();
  }
  EXPECT_THROW(plan_peen(DotText{}, PlannerKind::snake, PeenSetup{centred_window(20, 20), {}}),
               InputError);
  EXPECT_THROW(centred_window(-1, 5), InputError);
  EXPECT_EQ(parse_planner("block"), PlannerKind::block);
  EXPECT_FALSE(parse_planner("zigzag"));
}

// Hand-worked runs of the patent's steps on small matrices (rows from the top; pitch 1 mm, so
// cell (c, r) is at (c, −r)).
TEST(PeenBlockSnake, FiveBySevenAFollowsTheSixSteps) {
  const DotText a = matrix_text({".###.",   //
                                 "#...#",   //
                                 "#...#",   //
                                 "#####",   //
                                 "#...#",   //
                                 "#...#",   //
                                 "#...#"});
  const PeenPlan plan = plan_block_snake(a, a.bounds());
  // Step 1 finds (1,0); the top run ends the block (row 1 has nothing under [1,3]). Step 1 again,
  // row 1 searched right to left: (4,1) starts a block down the right side into the bar, run
  // leftwards; sensing row 4 from X2 = 0 toward 4 continues at (0,4) and pushes (4,4). The left
  // leg runs down to the bottom; (4,4) pops; last, step 1 finds (0,1) for the left shoulder.
  const std::vector<DotCell> expected = {{1, 0}, {2, 0}, {3, 0}, {4, 1}, {4, 2}, {4, 3},
                                         {3, 3}, {2, 3}, {1, 3}, {0, 3}, {0, 4}, {0, 5},
                                         {0, 6}, {4, 4}, {4, 5}, {4, 6}, {0, 1}, {0, 2}};
  EXPECT_EQ(struck_cells(a, plan), expected);
}

TEST(PeenBlockSnake, TwoWayPointRunsToOneEndThenBackToTheOther) {
  const DotText t = matrix_text({"..#..",  //
                                 "#####"});
  const PeenPlan plan = plan_block_snake(t, t.bounds());
  // The step down lands on (2,1), inside the run [0,4]: a two-way point. Both ends are two cells
  // away; the last direction was +x, so right first, then back past it to the left end.
  const std::vector<DotCell> expected = {{2, 0}, {2, 1}, {3, 1}, {4, 1}, {1, 1}, {0, 1}};
  EXPECT_EQ(struck_cells(t, plan), expected);
  // No turn points: every step lands on a dot.
  EXPECT_EQ(plan.stops.size(), expected.size());
}

TEST(PeenBlockSnake, SensingPushesOneStartPointPerStep) {
  const DotText t = matrix_text({"#####",  //
                                 "#.#.#"});
  const PeenPlan plan = plan_block_snake(t, t.bounds());
  // Row 0 runs 0→4; sensing row 1 from X2 = 4 toward 0: (4,1) continues the block, (2,1) is the
  // next different block and is pushed; claim 2 stops there, so (0,1) waits for step 1.
  const std::vector<DotCell> expected = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0},
                                         {4, 1}, {2, 1}, {0, 1}};
  EXPECT_EQ(struck_cells(t, plan), expected);
}

TEST(PeenBlockSnake, TrackMovesOneAxisAtATime) {
  const DotText t = matrix_text({"###..",  //
                                 "##...",  //
                                 ".....",  //
                                 "....#"});
  const PeenPlan plan = plan_block_snake(t, t.bounds());
  // Row 0 ends at X2 = 2; the step down lands on the empty (2,1): a corner, then the run 1→0.
  // The block ends; step 1 finds (4,3): along Y from (0,−1) to (0,−3), corner, then along X.
  ASSERT_EQ(plan.stops.size(), 8u);
  EXPECT_FALSE(plan.stops[3].dot);
  EXPECT_LT((plan.stops[3].pos_mm - Point(2, -1)).norm(), 1e-12);
  EXPECT_FALSE(plan.stops[6].dot);
  EXPECT_LT((plan.stops[6].pos_mm - Point(0, -3)).norm(), 1e-12);
  const std::vector<DotCell> expected = {{0, 0}, {1, 0}, {2, 0}, {1, 1}, {0, 1}, {4, 3}};
  EXPECT_EQ(struck_cells(t, plan), expected);
  // Without the corners the same strikes, straight moves.
  const PeenPlan straight = plan_block_snake(t, t.bounds(), false);
  EXPECT_EQ(straight.stops.size(), 6u);
  EXPECT_EQ(struck_cells(t, straight), expected);
}

TEST(PeenWindowSnake, SweepsEveryRowEdgeToEdge) {
  DotText t = matrix_text({"#.#",  //
                           ".#."});
  Box window;
  window.add(Point(-1, -2));
  window.add(Point(3, 0));
  const PeenPlan plan = plan_window_snake(t, window);
  EXPECT_EQ(plan.home_mm, Point(-1, 0));
  const std::vector<Point> expected = {{-1, 0}, {0, 0},  {2, 0},  {3, 0},  {3, -1},
                                       {1, -1}, {-1, -1}, {-1, -2}, {3, -2}};
  ASSERT_EQ(plan.stops.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_LT((plan.stops[i].pos_mm - expected[i]).norm(), 1e-12) << i;
  EXPECT_EQ(struck_cells(t, plan), (std::vector<DotCell>{{0, 0}, {2, 0}, {1, 1}}));
}

TEST(PeenOptimized, DeterministicAndNoSlowerThanItsFirstTour) {
  const DotText t = peen_test::serial_5x7();
  const GantryConfig g;
  const Point home = home_of(tight_window(t));
  const PeenPlan a = plan_optimized(t, home, g), b = plan_optimized(t, home, g);
  ASSERT_EQ(a.stops.size(), b.stops.size());
  for (std::size_t i = 0; i < a.stops.size(); ++i) EXPECT_EQ(a.stops[i].dot, b.stops[i].dot);
  TourOptions none;
  none.kicks_per_point = 0;
  const double searched = run_plan(plan_optimized(t, home, g, none), g).total_s;
  const double kicked = run_plan(a, g).total_s;
  EXPECT_LE(kicked, searched);
  // A 5x7 serial cannot be struck faster than one strike and one pitch move per dot.
  const double floor = static_cast<double>(t.dots.size()) *
                       (g.strike_s + axis_time_s(t.pitch_mm, g.x));
  EXPECT_GT(kicked, floor);
  EXPECT_LT(kicked, 1.15 * floor);
}

}  // namespace
}  // namespace mark
