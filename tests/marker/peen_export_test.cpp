// The plan as a move/strike CSV and as G-code: every strike once, positions on the step grid in
// plan order, times that add up to the simulated run.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "marker/peen/gantry_run.hpp"
#include "marker/peen/plan_export.hpp"
#include "peen_test_support.hpp"

namespace mark {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out(1);
  for (char c : s) {
    if (c == sep) out.emplace_back();
    else out.back() += c;
  }
  return out;
}

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out = split(s, '\n');
  if (!out.empty() && out.back().empty()) out.pop_back();
  return out;
}

struct Fixture {
  DotText text = peen_test::serial_5x7();
  GantryConfig gantry;
  PeenSetup setup{tight_window(text), gantry};
};

TEST(PeenExport, CsvListsEveryArrivalWithStepsAndTimes) {
  Fixture f;
  const PeenPlan plan = plan_peen(f.text, PlannerKind::block, f.setup);
  const GantryReport run = run_plan(plan, f.gantry, true);
  std::ostringstream out;
  write_plan_csv(out, plan, f.text, f.gantry);
  const std::vector<std::string> lines = lines_of(out.str());
  ASSERT_EQ(lines[0], "seq,action,x_mm,y_mm,x_steps,y_steps,dot,character,move_s,arrive_s");
  ASSERT_EQ(lines.size(), 2 + run.log.size());  // header, home, one row per logged arrival
  std::vector<int> hits(f.text.dots.size(), 0);
  std::size_t turns = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> c = split(lines[i], ',');
    ASSERT_EQ(c.size(), 10u) << lines[i];
    EXPECT_EQ(std::stoul(c[0]), i - 1);
    // Millimetres and steps agree: 40 steps per mm.
    EXPECT_NEAR(std::stod(c[2]) * 40, std::stod(c[4]), 1e-6);
    EXPECT_NEAR(std::stod(c[3]) * 40, std::stod(c[5]), 1e-6);
    if (c[1] == "strike") {
      const std::size_t dot = std::stoul(c[6]);
      ++hits.at(dot);
      EXPECT_EQ(std::stoul(c[7]), f.text.dots[dot].character);
      const StepPoint s = to_steps(f.text.dots[dot].pos_mm, f.gantry);
      EXPECT_EQ(std::stoll(c[4]), s.x);
      EXPECT_EQ(std::stoll(c[5]), s.y);
    } else if (c[1] == "turn") {
      ++turns;
      EXPECT_TRUE(c[6].empty());
    } else {
      EXPECT_EQ(c[1], "home");
      EXPECT_TRUE(i == 1 || i + 1 == lines.size());
    }
  }
  for (int h : hits) EXPECT_EQ(h, 1);
  EXPECT_GT(turns, 0u);  // the block snake turns at corners
  // The last arrival is home after every move and every strike but none after it.
  const std::vector<std::string> last = split(lines.back(), ',');
  EXPECT_NEAR(std::stod(last[9]), run.total_s, 1e-5);
}

TEST(PeenExport, GcodeMovesRapidlyAndFiresThePinOncePerDot) {
  Fixture f;
  const PeenPlan plan = plan_peen(f.text, PlannerKind::optimized, f.setup);
  const GantryReport run = run_plan(plan, f.gantry, true);
  std::ostringstream out;
  write_plan_gcode(out, plan, f.text, f.gantry);
  const std::vector<std::string> lines = lines_of(out.str());
  ASSERT_GE(lines.size(), 6u);
  EXPECT_EQ(lines.front(), "%");
  EXPECT_EQ(lines[3], "G21 G90");
  EXPECT_EQ(lines[lines.size() - 2], "M2");
  EXPECT_EQ(lines.back(), "%");
  std::size_t fires = 0, releases = 0, dwells = 0;
  std::vector<StepPoint> positions;
  for (const std::string& l : lines) {
    if (l == "M64 P0") ++fires;
    if (l == "M65 P0") ++releases;
    if (l == "G4 P0.0050") ++dwells;
    if (l.rfind("G0 X", 0) == 0) {
      const std::size_t y = l.find(" Y");
      ASSERT_NE(y, std::string::npos);
      // Four decimals, always with a decimal point.
      EXPECT_EQ(l.size() - l.find('.', y) - 1, 4u) << l;
      positions.push_back({std::llround(std::stod(l.substr(4, y - 4)) * 40),
                           std::llround(std::stod(l.substr(y + 2)) * 40)});
    }
  }
  EXPECT_EQ(fires, f.text.dots.size());
  EXPECT_EQ(releases, fires);
  EXPECT_EQ(dwells, fires);
  // The first G0 goes home; the rest are the simulated moves in order.
  ASSERT_EQ(positions.size(), 1 + run.moves);
  EXPECT_EQ(positions[0], to_steps(plan.home_mm, f.gantry));
  std::size_t k = 1;
  for (const GantryMove& m : run.log)
    if (!(m.to == m.from)) {
      EXPECT_EQ(positions.at(k++), m.to);
    }
}

TEST(PeenExport, ExtensionPicksTheFormatAndOthersAreRefused) {
  Fixture f;
  const PeenPlan plan = plan_peen(f.text, PlannerKind::snake, f.setup);
  try {
    export_plan("/tmp/plan.txt", plan, f.text, f.gantry);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("plan.txt"), std::string::npos);
  }
  EXPECT_THROW(export_plan("/nonexistent-dir/plan.csv", plan, f.text, f.gantry), InputError);
}

}  // namespace
}  // namespace mark
