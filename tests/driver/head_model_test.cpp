// Head presets: the τ values of dynamics.md §8, limits as documented, lookup by name.
#include "driver/head_model.hpp"

#include <gtest/gtest.h>

namespace mark {
namespace {

TEST(HeadModel, PresetsCarryTheReferenceTrackingErrors) {
  EXPECT_DOUBLE_EQ(head_sl10().tau_s, 0.12e-3);
  EXPECT_DOUBLE_EQ(head_sl14().tau_s, 0.21e-3);
  EXPECT_DOUBLE_EQ(head_cheap().tau_s, 0.25e-3);
  EXPECT_DOUBLE_EQ(head_sl10().max_speed_mm_s, 120 * 160.0);  // rad/s × f
  EXPECT_DOUBLE_EQ(head_sl14().max_speed_mm_s, 100 * 160.0);
  for (const HeadModel& h : {head_sl10(), head_sl14(), head_cheap(), head_sa14()}) {
    EXPECT_DOUBLE_EQ(h.field_mm, 110);
    EXPECT_DOUBLE_EQ(h.max_tick_s(), 0.2 * h.tau_s);
    EXPECT_GE(h.max_tick_s(), 10e-6);  // the default 10 µs tick is fine for every preset
  }
}

TEST(HeadModel, AccelerationsComeFromPublishedFiguresOrStepTimeBounds) {
  // excelliSCAN 14: 320 000 rad/s² and 200 rad/s optical at f = 160 mm.
  EXPECT_DOUBLE_EQ(head_sa14().max_accel_mm_s2, 320000 * 160.0);
  EXPECT_DOUBLE_EQ(head_sa14().max_speed_mm_s, 200 * 160.0);
  EXPECT_TRUE(head_sa14().second_order);
  // The others: at most the bang-bang bound 4·d/T² of a datasheet step (11 mm in T).
  EXPECT_LE(head_sl10().max_accel_mm_s2, 4 * 11 / (1.0e-3 * 1.0e-3) + 1);   // basiCube 10
  EXPECT_LE(head_sl14().max_accel_mm_s2, 4 * 11 / (1.9e-3 * 1.9e-3) + 1);   // intelliSCAN 20
  EXPECT_LE(head_cheap().max_accel_mm_s2, 4 * 11 / (1.2e-3 * 1.2e-3) + 1);  // SCANcube 10
}

TEST(HeadModel, SecondOrderNaturalFrequencyKeepsTheRampLag) {
  HeadModel h = head_sl14();
  h.zeta = 0.7;
  EXPECT_DOUBLE_EQ(2 * h.zeta / h.omega_n(), h.tau_s);
}

TEST(HeadModel, FoundByNameIgnoringCase) {
  ASSERT_TRUE(find_head("sl10").has_value());
  EXPECT_EQ(find_head("SL14")->name, "SL14");
  EXPECT_EQ(find_head("Cheap")->name, "cheap");
  EXPECT_FALSE(find_head("SL99").has_value());
  EXPECT_EQ(find_head("sa14")->name, "SA14");
  EXPECT_EQ(head_names().size(), 4u);
  for (const std::string& n : head_names()) EXPECT_EQ(find_head(n)->name, n);
}

}  // namespace
}  // namespace mark
