#pragma once
// Serial counters: what a counter is (its spec, from the job) and how it advances (its state,
// kept by the serial store). 64-bit signed integers throughout; a rendered value is never
// negative. One pure function, take(), issues the next value; both store backends call it
// inside their allocation transaction, so the rules live in one place:
//
//  - a new reset period (midnight or shift start in the counter's time zone) restarts the
//    counter at `start`, cycle 0;
//  - `marks_per_serial` parts get the same value (repeat 0, 1, …) before it advances by `step`;
//  - past the limit the counter stops with an error or wraps to `start` (cycle + 1).
//
// (period, cycle, value, repeat) identifies an issue: the store refuses to record one twice.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "base/error.hpp"
#include "marker/vars/alphabet.hpp"
#include "marker/vars/clock.hpp"
#include "marker/vars/shifts.hpp"
#include "marker/vars/time_zone.hpp"

namespace mark {

enum class EndPolicy { stop, wrap };
enum class ResetRule { never, midnight, shift };

std::string_view to_string(EndPolicy p);
std::optional<EndPolicy> parse_end_policy(std::string_view name);
std::string_view to_string(ResetRule r);
std::optional<ResetRule> parse_reset_rule(std::string_view name);

struct CounterSpec {
  std::string name;
  std::int64_t start = 1;
  std::int64_t step = 1;                 // not 0; negative counts down
  std::optional<std::int64_t> limit;     // last value issued; see effective_limit()
  EndPolicy at_limit = EndPolicy::stop;
  std::int64_t marks_per_serial = 1;     // parts marked with each value
  int width = 0;                         // digits (0: as many as needed); also the largest value
  Padding padding = Padding::keep;
  Alphabet alphabet;
  ResetRule reset = ResetRule::never;
  TimeZone time_zone = TimeZone::named("local");  // where midnight and shift starts are

  // The limit, or when unset: the largest value `width` digits hold (counting up; INT64_MAX
  // without a width) or 0 (counting down).
  std::int64_t effective_limit() const;
  // Whether `value` lies past the limit in counting direction (or below 0).
  bool beyond(std::int64_t value) const;
  // Throws InputError("<where>: ...") for a step of 0, marks_per_serial < 1, a negative start,
  // a limit behind the start, or a limit the width cannot hold.
  void validate(std::string_view where) const;
  // The value as text: alphabet, width, padding.
  void format(std::int64_t value, std::string& out) const { alphabet.format(value, width, padding, out); }
};

struct CounterState {
  std::int64_t next = 1;    // the value the next part gets, before the reset and limit rules
  std::int64_t used = 0;    // parts already marked with `next` (< marks_per_serial)
  std::string period;       // reset period this state belongs to ("" when never reset)
  std::int64_t cycle = 0;   // wraps in this period
  bool exhausted = false;   // the next value overflowed 64 bits (a stop at the limit)

  static CounterState fresh(const CounterSpec& spec, std::string period);
};

// One value consumed by one part.
struct Issue {
  std::string counter;
  std::int64_t value = 0;
  std::int64_t repeat = 0;  // 0 .. marks_per_serial − 1
  std::string period;
  std::int64_t cycle = 0;
};

// The counter has passed its limit and its end policy is stop.
class SerialLimitError : public InputError {
 public:
  using InputError::InputError;
};

// The reset period `now` falls in for this counter: "" (never), the local date (midnight), or
// the shift occurrence ("2026-03-05/C"; needs the job's shifts).
std::string period_key(const CounterSpec& spec, SysTime now, const ShiftTable& shifts);

// Periods only move forward. The period a part belongs to at `now`: the period of `now`, unless
// the clock stands behind the stored period (stepped back across a midnight or a shift start) —
// then the stored period is kept and `stepped_back` says so, because restarting a period the
// counter has already counted in would issue its values a second time.
struct PeriodChoice {
  std::string period;
  bool stepped_back = false;
  std::string clock_period;  // the period of `now` (differs from `period` when stepped back)
};
PeriodChoice current_period(const CounterSpec& spec, const CounterState& state, SysTime now,
                            const ShiftTable& shifts);
// The instant period `key` began: its local midnight, or its shift's start, in the counter's
// time zone. Nothing for "" and for a key of another rule (or of a shift no longer in the table).
// A part whose clock stands behind its counter's period is dated at this instant, so its date
// and shift fields name the period its number belongs to.
std::optional<SysTime> period_start(const CounterSpec& spec, const std::string& key, const ShiftTable& shifts);
// Whether reset period `a` began before `b` (keys of period_key(); "" — never reset — and keys
// of another reset rule or of a shift no longer in the table are not ordered: false).
bool period_before(const CounterSpec& spec, const std::string& a, const std::string& b,
                   const ShiftTable& shifts);

// Issues the next value and advances `state`. Throws SerialLimitError (state unchanged) when
// the counter is past its limit and stops there.
Issue take(const CounterSpec& spec, CounterState& state, const std::string& period);

// What take() would issue next, without changing anything (nothing when it would throw).
std::optional<Issue> peek(const CounterSpec& spec, const CounterState& state,
                          const std::string& period);

}  // namespace mark
