// Periods only move forward: the order of reset periods (midnight, shift starts in the table's
// order, not the codes' alphabet), the period a part belongs to when the clock stands behind
// its counter's, and the instant a period began (in the counter's time zone, across DST).
#include <gtest/gtest.h>

#include <date/date.h>

#include "marker/vars/counter.hpp"
#include "tests/marker/vars/at_utc.hpp"

namespace mark {
namespace {

using namespace std::chrono;

using test::at_utc;

CounterSpec counter(ResetRule reset, const char* zone = "UTC") {
  CounterSpec s;
  s.name = "sn";
  s.reset = reset;
  s.time_zone = TimeZone::named(zone);
  return s;
}

// Night shift "N" at 22:00 sorts before "M" (06:00) alphabetically but runs after it.
const ShiftTable kShifts({{"M", 6 * 60}, {"A", 14 * 60}, {"N", 22 * 60}});

TEST(PeriodOrder, MidnightKeysAreDates) {
  const CounterSpec c = counter(ResetRule::midnight);
  EXPECT_TRUE(period_before(c, "2026-03-05", "2026-03-06", {}));
  EXPECT_TRUE(period_before(c, "2025-12-31", "2026-01-01", {}));
  EXPECT_FALSE(period_before(c, "2026-03-06", "2026-03-05", {}));
  EXPECT_FALSE(period_before(c, "2026-03-05", "2026-03-05", {}));
  EXPECT_FALSE(period_before(c, "", "2026-03-05", {}));  // a counter that never reset: not ordered
}

TEST(PeriodOrder, ShiftKeysFollowTheTableNotTheCodes) {
  const CounterSpec c = counter(ResetRule::shift);
  EXPECT_TRUE(period_before(c, "2026-03-05/M", "2026-03-05/N", kShifts));
  EXPECT_TRUE(period_before(c, "2026-03-05/A", "2026-03-05/N", kShifts));
  EXPECT_FALSE(period_before(c, "2026-03-05/N", "2026-03-05/M", kShifts));
  EXPECT_TRUE(period_before(c, "2026-03-05/N", "2026-03-06/M", kShifts));
  EXPECT_FALSE(period_before(c, "2026-03-05/X", "2026-03-05/N", kShifts));  // X: not in the table
}

TEST(PeriodOrder, AClockBehindTheCountersPeriodKeepsIt) {
  const CounterSpec c = counter(ResetRule::midnight);
  CounterState st = CounterState::fresh(c, "2026-03-06");
  // 23:55 the evening before: the counter stays in the 6th.
  PeriodChoice p = current_period(c, st, at_utc(2026, 3, 5, 23, 55), {});
  EXPECT_TRUE(p.stepped_back);
  EXPECT_EQ(p.period, "2026-03-06");
  EXPECT_EQ(p.clock_period, "2026-03-05");
  // Forward is a new period as always.
  p = current_period(c, st, at_utc(2026, 3, 7, 0, 1), {});
  EXPECT_FALSE(p.stepped_back);
  EXPECT_EQ(p.period, "2026-03-07");
  // A counter created before its first period ("") moves into any period.
  st.period = "";
  EXPECT_FALSE(current_period(c, st, at_utc(2026, 3, 5, 12, 0), {}).stepped_back);
}

TEST(PeriodOrder, APeriodStartsAtItsLocalMidnightOrShift) {
  // Berlin: 2026-03-29 02:00 CET → 03:00 CEST; midnight of the 29th is 23:00 UTC on the 28th,
  // of the 30th 22:00 UTC on the 29th.
  const CounterSpec c = counter(ResetRule::midnight, "Europe/Berlin");
  EXPECT_EQ(period_start(c, "2026-03-29", {}), at_utc(2026, 3, 28, 23, 0));
  EXPECT_EQ(period_start(c, "2026-03-30", {}), at_utc(2026, 3, 29, 22, 0));
  const CounterSpec s = counter(ResetRule::shift, "Europe/Berlin");
  EXPECT_EQ(period_start(s, "2026-03-30/N", kShifts), at_utc(2026, 3, 30, 20, 0));
  EXPECT_FALSE(period_start(s, "2026-03-30/X", kShifts));
  EXPECT_FALSE(period_start(counter(ResetRule::never), "", {}));
}

}  // namespace
}  // namespace mark
