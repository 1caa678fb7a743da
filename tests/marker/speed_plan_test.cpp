// Look-ahead speed planning: junction speeds (a stop at corners and wherever the laser switches,
// full speed through tangential joins), reachable entry and exit speeds on every move, the
// curvature limit, the speed profile's closed form, and the limits checked on the stream of
// samples the planned job produces.
#include "marker/plan/speed_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "base/numbers.hpp"
#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/layout/layout.hpp"
#include "marker/locus/locus_generator.hpp"
#include "marker/plan/plan.hpp"
#include "marker/plan/speed_profile.hpp"
#include "tests/marker/plan_test_support.hpp"

namespace mark {
namespace {

Pen lookahead_pen(double speed = 2000, bool feed_forward = false) {
  PenRules r;
  r.lookahead = true;
  r.feed_forward = feed_forward;
  r.accel_share = r.jump_accel_share = r.curve_accel_share = 0.5;
  return pen_for_head(head_sl10(), CornerStrategy::none, speed, 10e-6, r);
}

TEST(SpeedProfile, TrapezoidAndTriangle) {
  // 10 mm from rest to rest at 1e7 mm/s², cruise 1000 mm/s: 0.1 ms up (0.05 mm), 9.9 mm at
  // 1000 mm/s, 0.1 ms down.
  const SpeedProfile p = SpeedProfile::make(10, 0, 0, 1000, 1e7, 1e7);
  EXPECT_DOUBLE_EQ(p.vp, 1000);
  EXPECT_NEAR(p.duration, 0.2e-3 + 9.9 / 1000, 1e-12);
  EXPECT_NEAR(p.position(p.t1), 0.05, 1e-12);
  EXPECT_NEAR(p.position(p.duration), 10, 1e-12);
  EXPECT_NEAR(p.speed(p.duration / 2), 1000, 1e-9);
  // Too short to cruise: a triangle with the peak √(a·L).
  const SpeedProfile t = SpeedProfile::make(0.01, 0, 0, 1000, 1e7, 1e7);
  EXPECT_NEAR(t.vp, std::sqrt(1e7 * 0.01), 1e-9);
  EXPECT_NEAR(t.duration, 2 * std::sqrt(0.01 / 1e7), 1e-12);
  // Entered and left at speed, different rates.
  const SpeedProfile e = SpeedProfile::make(1, 500, 200, 800, 1e7, 2e7);
  EXPECT_NEAR(e.speed(0), 500, 1e-9);
  EXPECT_NEAR(e.speed(e.duration), 200, 1e-9);
  EXPECT_NEAR(e.position(e.duration), 1, 1e-12);
}

TEST(SpeedPlan, StopsAtCornersAndPassesTangentialJoins) {
  // An L (90° corner) followed, after a jump, by a line running tangentially into an arc.
  const Figure f = test::figure_of(
      {{Element::line({0, 0}, {2, 0}), Element::line({2, 0}, {2, 2})},
       {Element::line({5, 0}, {7, 0}), Element::arc({7, 0.05}, 0.05, -kPi / 2, kPi / 2)}});
  const Plan plan = plan_figure(f, lookahead_pen());
  std::vector<const Command*> lit;
  for (const Command& c : plan.commands)
    if (c.laser()) lit.push_back(&c);
  ASSERT_EQ(lit.size(), 4u);
  EXPECT_EQ(lit[0]->entry_speed_mm_s, 0);   // the laser switches on at rest
  // 90° corner: the velocity steps by at most the junction's Δv (the head's headroom over one
  // tick is larger here), 2·v·sin 45° ≤ Δv.
  EXPECT_NEAR(lit[0]->exit_speed_mm_s, plan.pen.junction_dv_mm_s / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(lit[1]->exit_speed_mm_s, 0);    // the laser switches off at rest
  EXPECT_GT(lit[2]->exit_speed_mm_s, 500);  // straight into the arc at its curve speed
  EXPECT_NEAR(lit[2]->exit_speed_mm_s, lit[3]->entry_speed_mm_s, 1e-9);
  // The arc: at most √(a_c·r).
  EXPECT_NEAR(lit[3]->speed_mm_s, std::sqrt(plan.pen.curve_accel_mm_s2 * 0.05), 1e-6);
  EXPECT_NEAR(lit[2]->exit_speed_mm_s, lit[3]->speed_mm_s, 1e-6);
  // Lit power is full at the fastest lit speed of the job.
  for (const Command* c : lit) EXPECT_DOUBLE_EQ(c->full_power_speed_mm_s, 2000);
}

TEST(SpeedPlan, EveryMoveReachesItsExitFromItsEntry) {
  LayoutOptions lo;
  lo.height_mm = 1;
  const Figure f = layout_text("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789",
                               *open_font(kBuiltinFontName), lo);
  for (CornerStrategy corner : {CornerStrategy::none, CornerStrategy::delays, CornerStrategy::blanking}) {
    PenRules r;
    r.feed_forward = true;
    const Plan plan = plan_figure(f, pen_for_head(head_sl10(), corner, 3000, 10e-6, r));
    double prev_exit = 0;
    for (const Command& c : plan.commands) {
      if (c.kind == CommandKind::dwell) {
        EXPECT_EQ(prev_exit, 0);
        continue;
      }
      ASSERT_TRUE(c.planned());
      EXPECT_NEAR(c.entry_speed_mm_s, prev_exit, 1e-9);  // speed is continuous
      const double dv2 = std::abs(c.exit_speed_mm_s * c.exit_speed_mm_s -
                                  c.entry_speed_mm_s * c.entry_speed_mm_s);
      EXPECT_LE(dv2, 2 * std::max(c.accel_mm_s2, c.decel_mm_s2) * c.length * (1 + 1e-9) + 1e-9);
      EXPECT_LE(c.entry_speed_mm_s, c.speed_mm_s + 1e-9);
      prev_exit = c.exit_speed_mm_s;
    }
    EXPECT_EQ(prev_exit, 0);  // the job ends at rest
  }
}

TEST(SpeedPlan, EllipseSmallestRadiusOfCurvature) {
  // rx = 2, ry = 1: ρ = ry²/rx = 0.5 at the ends of the long axis, rx²/ry = 4 at the others.
  EXPECT_NEAR(min_radius_mm(Element::ellipse({0, 0}, 2, 1, 0.3, -0.5, 1.0)), 0.5, 1e-12);
  EXPECT_NEAR(min_radius_mm(Element::ellipse({0, 0}, 2, 1, 0, kPi / 2 - 0.1, 0.2)), 4 * std::pow(std::sin(kPi / 2 - 0.1) * std::sin(kPi / 2 - 0.1) * 4 + std::cos(kPi / 2 - 0.1) * std::cos(kPi / 2 - 0.1), 1.5) / 8, 1e-9);
  EXPECT_TRUE(std::isinf(min_radius_mm(Element::line({0, 0}, {1, 0}))));
}

// The samples of a planned job (feed-forward off: the desired beam path itself), per axis:
// speed and acceleration by finite differences never above the head's limits.
TEST(SpeedPlan, PlannedStreamStaysWithinTheHeadsLimits) {
  LayoutOptions lo;
  lo.height_mm = 1;
  lo.align = Align::center;
  const Figure f = layout_text("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789",
                               *open_font(kBuiltinFontName), lo);
  const HeadModel head = head_sl10();
  PenRules r;
  r.lookahead = true;
  r.accel_share = r.jump_accel_share = r.curve_accel_share = 0.95;  // the most cps ever uses
  const Plan plan = plan_figure(f, pen_for_head(head, CornerStrategy::none, 8000, 10e-6, r));
  LocusGenerator gen(plan);
  std::vector<ScanSample> s(LocusGenerator::count_samples(plan));
  ASSERT_EQ(gen.generate(s.data(), s.size()), s.size());
  const double T = plan.pen.tick_s;
  double top_v = 0, top_a = 0;
  Point prev_v(0, 0), prev(0, 0);
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Point p(s[k].x_mm, s[k].y_mm);
    const Point v = (p - prev) / T;
    const Point a = (v - prev_v) / T;
    top_v = std::max({top_v, std::abs(v.x()), std::abs(v.y())});
    top_a = std::max({top_a, std::abs(a.x()), std::abs(a.y())});
    prev = p, prev_v = v;
  }
  EXPECT_LE(top_v, head.max_speed_mm_s);
  EXPECT_LE(top_v, 0.5 * head.max_speed_mm_s + 1);  // jumps at half the limit (+ float rounding)
  // Float samples: the second difference of positions ~50 mm from the origin carries ~4e-6 mm
  // of rounding per tick, i.e. ±4e4 mm/s² — 0.1 % of the limit.
  EXPECT_LE(top_a, head.max_accel_mm_s2 * 1.001);
  EXPECT_GT(top_a, 0.5 * head.max_accel_mm_s2);  // and it does use the head
}

}  // namespace
}  // namespace mark
