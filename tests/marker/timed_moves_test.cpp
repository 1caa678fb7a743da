// The locus as timed moves for a board with its own clock (marker/job/timed_moves.hpp): replayed
// the way the board runs them — each move straight and evenly timed over its ticks — every
// sample of the locus is matched within the tolerance, with its laser bit, its power within
// the spread, and the moves' ticks add up to the locus's.
#include "marker/job/timed_moves.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "marker/locus/locus_generator.hpp"
#include "tests/marker/plan_test_support.hpp"

namespace mark {
namespace {

constexpr double kTick = 10e-6;

// The board's reading of timed moves: sample k of an n-tick move at k/n of the way.
std::vector<ScanSample> replay(const std::vector<DeviceCommand>& moves, ScanSample at) {
  std::vector<ScanSample> out;
  for (const DeviceCommand& c : moves) {
    if (c.op == DeviceOp::pen) continue;
    const auto n = static_cast<std::size_t>(std::lround(c.duration_s / kTick));
    for (std::size_t k = 1; k <= n; ++k) {
      const double f = double(k) / double(n);
      ScanSample s;
      s.x_mm = static_cast<float>(at.x_mm + (c.x_mm - at.x_mm) * f);
      s.y_mm = static_cast<float>(at.y_mm + (c.y_mm - at.y_mm) * f);
      s.laser = c.op == DeviceOp::mark;
      s.power = static_cast<std::uint8_t>(std::lround(c.power_fraction * 255));
      out.push_back(s);
    }
    at.x_mm = static_cast<float>(c.x_mm), at.y_mm = static_cast<float>(c.y_mm);
  }
  return out;
}

// A locus with what look-ahead makes: a dark start, a lit line speeding up from rest with power
// ∝ speed, a lit hold, a circle at constant speed, a dark jump, a lit stroke slowing down.
std::vector<ScanSample> synthetic_locus() {
  std::vector<ScanSample> s;
  const auto add = [&](double x, double y, bool lit, double power) {
    s.push_back({static_cast<float>(x), static_cast<float>(y), lit,
                 static_cast<std::uint8_t>(std::lround(std::clamp(power, 0.0, 1.0) * 255))});
  };
  for (int k = 0; k < 20; ++k) add(0, 0, false, 1);
  const double a = 2e6;  // mm/s²: 2 m/s after 1 ms
  for (int k = 1; k <= 100; ++k) {
    const double t = k * kTick;
    add(0.5 * a * t * t, 0, true, a * t / 2000);
  }
  const double x0 = s.back().x_mm;
  for (int k = 0; k < 30; ++k) add(x0, 0, true, 1);
  for (int k = 1; k <= 300; ++k) {
    const double phi = 2 * std::numbers::pi * k / 300;
    add(x0 - 0.3 + 0.3 * std::cos(phi), 0.3 * std::sin(phi), true, 0.6);
  }
  for (int k = 1; k <= 40; ++k) add(x0 + 0.05 * k, 0.02 * k, false, 1);
  const double x1 = s.back().x_mm, y1 = s.back().y_mm;
  for (int k = 1; k <= 80; ++k) {
    const double t = k * kTick, v0 = 1500;
    add(x1 + v0 * t - 0.5 * 1.5e7 * t * t, y1, true, (v0 - 1.5e7 * t) / 2000);
  }
  return s;
}

TEST(TimedMoves, ReplayedEvenlyEverySampleIsWithinTheTolerance) {
  const std::vector<ScanSample> locus = synthetic_locus();
  std::vector<DeviceCommand> moves;
  TimedMoveLimits limits;
  TimedMoves cut(kTick, moves, limits);
  // In blocks of odd sizes, as the locus generator hands them out.
  for (std::size_t at = 0; at < locus.size(); at += 37)
    cut.add(std::span(locus).subspan(at, std::min<std::size_t>(37, locus.size() - at)));
  cut.finish();
  const std::vector<ScanSample> board = replay(moves, locus.front());
  ASSERT_EQ(board.size(), locus.size() - 1);
  double worst = 0;
  for (std::size_t k = 0; k < board.size(); ++k) {
    const ScanSample& want = locus[k + 1];
    worst = std::max(worst, std::hypot(double(board[k].x_mm) - want.x_mm, double(board[k].y_mm) - want.y_mm));
    ASSERT_EQ(board[k].laser, want.laser) << k;
    if (want.laser) {
      EXPECT_LE(std::abs(int(board[k].power) - int(want.power)), limits.power_spread) << k;
    }
  }
  EXPECT_LE(worst, limits.tolerance_mm + 1e-6);
  EXPECT_NEAR(cut.max_error_mm(), worst, 1e-6);
  // Far fewer moves than samples, but the speeding-up line needs many.
  EXPECT_LT(moves.size(), locus.size() / 4);
  EXPECT_GT(moves.size(), 10u);
}

TEST(TimedMoves, AConstantSpeedLineIsOneMovePerLongestSpan) {
  std::vector<ScanSample> locus;
  for (int k = 0; k <= 1000; ++k) locus.push_back({static_cast<float>(0.01 * k), 0, true, 200});
  std::vector<DeviceCommand> moves;
  TimedMoves cut(kTick, moves);
  cut.add(locus);
  cut.finish();
  ASSERT_EQ(moves.size(), 4u);  // ⌈1000 / 256⌉
  double ticks = 0;
  for (const DeviceCommand& m : moves) {
    EXPECT_EQ(m.op, DeviceOp::mark);
    EXPECT_NEAR(m.speed_mm_s, 1000, 1e-3);
    EXPECT_NEAR(m.power_fraction, 200.0 / 255, 1e-9);
    ticks += m.duration_s / kTick;
  }
  EXPECT_NEAR(ticks, 1000, 1e-6);
  EXPECT_NEAR(moves.back().x_mm, 10, 1e-5);
}

TEST(TimedMoves, AFeedForwardPlanBecomesTheLocusCheckedAgainstTheField) {
  // The plan a look-ahead / feed-forward pen gives a command-level device is the host's own; its
  // program is the locus, tick for tick, with a pen that carries no delays.
  Pen pen;
  pen.corner = CornerStrategy::none;
  pen.lookahead = true;
  pen.accel_mm_s2 = pen.curve_accel_mm_s2 = 2e6;
  pen.jump_accel_mm_s2 = 2e7;
  pen.junction_dv_mm_s = 100;
  pen.ff_lag_s = 120e-6;
  pen.laser_on_delay_s = pen.laser_off_delay_s = 0;
  const Figure figure = test::figure_of({{Element::line({1, 1}, {3, 1}), Element::line({3, 1}, {3, 2})},
                                        {Element::arc({5, 1}, 0.5, 0, 2 * std::numbers::pi)}});
  const Plan plan = plan_for_device(figure, pen, StrokeOrder::glyph);
  ASSERT_TRUE(timed_on_board(plan.pen));
  DeviceDescription board;
  board.level = DeviceLevel::commands;
  board.field_mm = 110;
  const DeviceProgram program = device_program(plan, LaserSettings{}, board);
  EXPECT_EQ(program.pen.laser_on_delay_s, 0);
  EXPECT_EQ(program.pen.jump_delay_s, 0);
  EXPECT_EQ(program.pen.polygon_delay_s, 0);
  double ticks = 0;
  for (const DeviceCommand& c : program.commands) ticks += c.duration_s / plan.pen.tick_s;
  EXPECT_NEAR(ticks, double(LocusGenerator::count_samples(plan)) - 1, 2.0);
  // The same plan on a board whose field the text leaves.
  board.field_mm = 1;
  EXPECT_THROW(device_program(plan, LaserSettings{}, board), DeviceFaultError);
}

}  // namespace
}  // namespace mark
