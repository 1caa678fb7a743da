// Serial counters: steps (also negative), limits with stop and wrap, marks per serial, resets at
// midnight and at shift start in the counter's time zone, with fixed clocks.
#include <gtest/gtest.h>

#include <date/date.h>

#include "marker/vars/counter.hpp"
#include "tests/marker/vars/at_utc.hpp"

namespace mark {
namespace {

using namespace std::chrono;

using test::at_utc;

CounterSpec spec(std::int64_t start, std::int64_t step) {
  CounterSpec s;
  s.name = "sn";
  s.start = start;
  s.step = step;
  s.time_zone = TimeZone::named("UTC");
  return s;
}

std::vector<std::int64_t> take_n(const CounterSpec& s, CounterState& st, int n,
                                 const std::string& period = "") {
  std::vector<std::int64_t> v;
  for (int i = 0; i < n; ++i) v.push_back(take(s, st, period).value);
  return v;
}

TEST(Counter, CountsUpFromStartByStep) {
  const CounterSpec s = spec(100, 5);
  CounterState st = CounterState::fresh(s, "");
  EXPECT_EQ(take_n(s, st, 4), (std::vector<std::int64_t>{100, 105, 110, 115}));
  EXPECT_EQ(st.next, 120);
}

TEST(Counter, NegativeStepCountsDownAndStopsAtZeroByDefault) {
  const CounterSpec s = spec(3, -1);
  CounterState st = CounterState::fresh(s, "");
  EXPECT_EQ(take_n(s, st, 4), (std::vector<std::int64_t>{3, 2, 1, 0}));
  EXPECT_THROW(take(s, st, ""), SerialLimitError);
  EXPECT_EQ(st.next, -1);  // unchanged by the refusal
}

TEST(Counter, StopAtLimitRefusesAndLeavesTheStateAlone) {
  CounterSpec s = spec(1, 2);
  s.limit = 5;
  CounterState st = CounterState::fresh(s, "");
  EXPECT_EQ(take_n(s, st, 3), (std::vector<std::int64_t>{1, 3, 5}));
  const CounterState before = st;
  try {
    take(s, st, "");
    FAIL() << "no error past the limit";
  } catch (const SerialLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("counter 'sn' has passed its limit 5"), std::string::npos);
  }
  EXPECT_EQ(st.next, before.next);
  EXPECT_FALSE(peek(s, st, ""));
}

TEST(Counter, WrapRestartsAtStartInTheNextCycle) {
  CounterSpec s = spec(7, 1);
  s.limit = 9;
  s.at_limit = EndPolicy::wrap;
  CounterState st = CounterState::fresh(s, "");
  std::vector<std::pair<std::int64_t, std::int64_t>> seen;
  for (int i = 0; i < 7; ++i) {
    const Issue is = take(s, st, "");
    seen.emplace_back(is.value, is.cycle);
  }
  EXPECT_EQ(seen, (std::vector<std::pair<std::int64_t, std::int64_t>>{
                      {7, 0}, {8, 0}, {9, 0}, {7, 1}, {8, 1}, {9, 1}, {7, 2}}));
}

TEST(Counter, WrapCountingDown) {
  CounterSpec s = spec(2, -1);
  s.at_limit = EndPolicy::wrap;
  CounterState st = CounterState::fresh(s, "");
  EXPECT_EQ(take_n(s, st, 5), (std::vector<std::int64_t>{2, 1, 0, 2, 1}));
}

TEST(Counter, WidthBoundsTheImplicitLimit) {
  CounterSpec s = spec(998, 1);
  s.width = 3;
  CounterState st = CounterState::fresh(s, "");
  EXPECT_EQ(s.effective_limit(), 999);
  EXPECT_EQ(take_n(s, st, 2), (std::vector<std::int64_t>{998, 999}));
  EXPECT_THROW(take(s, st, ""), SerialLimitError);
  s.alphabet = *Alphabet::named("hex");
  EXPECT_EQ(s.effective_limit(), 0xFFF);
}

TEST(Counter, MarksPerSerialRepeatsEachValue) {
  CounterSpec s = spec(1, 1);
  s.marks_per_serial = 3;
  CounterState st = CounterState::fresh(s, "");
  std::vector<std::pair<std::int64_t, std::int64_t>> seen;
  for (int i = 0; i < 7; ++i) {
    const Issue is = take(s, st, "");
    seen.emplace_back(is.value, is.repeat);
  }
  EXPECT_EQ(seen, (std::vector<std::pair<std::int64_t, std::int64_t>>{
                      {1, 0}, {1, 1}, {1, 2}, {2, 0}, {2, 1}, {2, 2}, {3, 0}}));
}

TEST(Counter, SixtyFourBitsWithoutFloatRounding) {
  // SAMLight's standalone float32 serials repeat above 2^24; ours are exact to 2^63 − 1.
  CounterSpec s = spec(16'777'215, 1);
  CounterState st = CounterState::fresh(s, "");
  EXPECT_EQ(take_n(s, st, 3), (std::vector<std::int64_t>{16'777'215, 16'777'216, 16'777'217}));
  CounterSpec big = spec(INT64_MAX - 1, 1);
  CounterState bs = CounterState::fresh(big, "");
  EXPECT_EQ(take_n(big, bs, 2), (std::vector<std::int64_t>{INT64_MAX - 1, INT64_MAX}));
  EXPECT_TRUE(bs.exhausted);
  EXPECT_THROW(take(big, bs, ""), SerialLimitError);
}

TEST(Counter, MidnightResetInTheCountersTimeZone) {
  CounterSpec s = spec(1, 1);
  s.reset = ResetRule::midnight;
  s.time_zone = TimeZone::named("Europe/Berlin");
  const ShiftTable none;
  // 22:30 UTC on 5 March is 23:30 in Berlin (CET, +1): still the 5th.
  const std::string p1 = period_key(s, at_utc(2026, 3, 5, 22, 30), none);
  // 23:10 UTC is 00:10 on the 6th in Berlin: a new day, although UTC is still on the 5th.
  const std::string p2 = period_key(s, at_utc(2026, 3, 5, 23, 10), none);
  EXPECT_EQ(p1, "2026-03-05");
  EXPECT_EQ(p2, "2026-03-06");
  CounterState st = CounterState::fresh(s, p1);
  EXPECT_EQ(take_n(s, st, 3, p1), (std::vector<std::int64_t>{1, 2, 3}));
  const Issue first = take(s, st, p2);
  EXPECT_EQ(first.value, 1);
  EXPECT_EQ(first.period, "2026-03-06");
  EXPECT_EQ(take(s, st, p2).value, 2);
  // Summer time: 22:10 UTC on 1 July is 00:10 on the 2nd in Berlin (CEST, +2).
  EXPECT_EQ(period_key(s, at_utc(2026, 7, 1, 22, 10), none), "2026-07-02");
}

TEST(Counter, ShiftStartResetsAndTheNightShiftBelongsToItsFirstDay) {
  CounterSpec s = spec(1, 1);
  s.reset = ResetRule::shift;
  const ShiftTable shifts({{"A", 6 * 60}, {"B", 14 * 60}, {"C", 22 * 60}});
  EXPECT_EQ(period_key(s, at_utc(2026, 3, 5, 5, 59), shifts), "2026-03-04/C");
  EXPECT_EQ(period_key(s, at_utc(2026, 3, 5, 6, 0), shifts), "2026-03-05/A");
  EXPECT_EQ(period_key(s, at_utc(2026, 3, 5, 13, 59), shifts), "2026-03-05/A");
  EXPECT_EQ(period_key(s, at_utc(2026, 3, 5, 14, 0), shifts), "2026-03-05/B");
  EXPECT_EQ(period_key(s, at_utc(2026, 3, 5, 23, 30), shifts), "2026-03-05/C");
  EXPECT_EQ(period_key(s, at_utc(2026, 3, 6, 1, 0), shifts), "2026-03-05/C");
  CounterState st = CounterState::fresh(s, "2026-03-05/A");
  EXPECT_EQ(take_n(s, st, 2, "2026-03-05/A"), (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(take(s, st, "2026-03-05/B").value, 1);
  // Midnight inside the night shift does not reset a shift counter.
  EXPECT_EQ(take(s, st, "2026-03-05/C").value, 1);
  EXPECT_EQ(take(s, st, "2026-03-05/C").value, 2);
}

TEST(Counter, ValidationNamesTheField) {
  auto message = [](CounterSpec s) {
    try {
      s.validate("counters.sn");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(message(spec(1, 0)), "counters.sn.step: a counter's step cannot be 0");
  CounterSpec s = spec(10, 1);
  s.limit = 5;
  EXPECT_EQ(message(s), "counters.sn.limit: 5 lies behind the start 10 for a step of 1");
  s = spec(1, 1);
  s.limit = 1000;
  s.width = 3;
  EXPECT_EQ(message(s),
            "counters.sn.width: 1000 needs 4 decimal digits, the width is 3 (lower the limit or "
            "widen the field)");
  s = spec(-1, 1);
  EXPECT_EQ(message(s), "counters.sn.start: a serial number cannot be negative, got -1");
  s = spec(1, 1);
  s.marks_per_serial = 0;
  EXPECT_EQ(message(s), "counters.sn.marks_per_serial: must be at least 1, got 0");
  EXPECT_EQ(message(spec(5, -1)), "(accepted)");
}

}  // namespace
}  // namespace mark
