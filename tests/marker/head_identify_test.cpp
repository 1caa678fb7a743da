// Head identification: the test pattern run on the simulated heads and fitted from the record
// alone recovers each preset's parameters within 2 % — τ for first-order heads, ωn and ζ for
// second-order ones, and the speed and acceleration limits.
#include <gtest/gtest.h>

#include "base/error.hpp"
#include "driver/sim/head_response.hpp"
#include "marker/head/head_fit.hpp"

namespace mark {
namespace {

SimScannerOptions sim_of(const HeadModel& h) {
  SimScannerOptions o;
  o.head = h;
  return o;
}

void expect_within(double got, double want, double share, const std::string& what) {
  EXPECT_NEAR(got / want, 1.0, share) << what << ": fitted " << got << ", preset " << want;
}

void expect_recovers(const HeadModel& h) {
  const HeadProfile p = identify_head(sim_of(h));
  const std::string name = h.name + (h.second_order ? " (second order)" : "");
  EXPECT_EQ(p.model, h.second_order ? ServoOrder::second : ServoOrder::first) << name;
  if (h.second_order) {
    expect_within(p.omega_n_rad_s, h.omega_n(), 0.02, name + " ωn");
    expect_within(p.zeta, h.zeta, 0.02, name + " ζ");
  } else {
    expect_within(p.tau_s, h.tau_s, 0.02, name + " τ");
  }
  expect_within(p.lag_s(), h.tau_s, 0.02, name + " ramp lag");
  expect_within(p.max_speed_mm_s, h.max_speed_mm_s, 0.02, name + " speed limit");
  expect_within(p.max_accel_mm_s2, h.max_accel_mm_s2, 0.02, name + " acceleration limit");
  EXPECT_DOUBLE_EQ(p.field_mm, h.field_mm);
  EXPECT_EQ(p.source, "identified");
}

TEST(HeadIdentify, RecoversTheFirstOrderPresets) {
  for (const HeadModel& h : {head_sl10(), head_sl14(), head_cheap()}) expect_recovers(h);
}

TEST(HeadIdentify, RecoversTheSecondOrderFeedForwardPreset) { expect_recovers(head_sa14()); }

TEST(HeadIdentify, RecoversSecondOrderVariantsOfAFirstOrderHead) {
  for (double zeta : {0.5, 0.7, 1.0}) {
    HeadModel h = head_sl10();
    h.second_order = true;
    h.zeta = zeta;
    expect_recovers(h);
  }
}

TEST(HeadIdentify, PatternDependsOnlyOnFieldAndTick) {
  const ResponsePattern a = head_response_pattern(110), b = head_response_pattern(110);
  ASSERT_EQ(a.commands.size(), b.commands.size());
  ASSERT_FALSE(a.parts.empty());
  // Every part is inside the field and the laser stays off.
  for (const ScanSample& s : a.commands) {
    EXPECT_FALSE(s.laser);
    EXPECT_LE(std::abs(s.x_mm), 55.0f);
    EXPECT_LE(std::abs(s.y_mm), 55.0f);
  }
}

TEST(HeadIdentify, ARecordWithoutMotionIsRefused) {
  ResponseRecord r;
  r.pattern = head_response_pattern(110);
  r.position.assign(r.pattern.commands.size(), Vec2{0, 0});
  EXPECT_THROW(fit_head_profile(r, "stuck", 110), InputError);
}

}  // namespace
}  // namespace mark
