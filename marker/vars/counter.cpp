#include "marker/vars/counter.hpp"

#include <date/date.h>

#include <cstdio>

namespace mark {

std::string_view to_string(EndPolicy p) { return p == EndPolicy::stop ? "stop" : "wrap"; }

std::optional<EndPolicy> parse_end_policy(std::string_view name) {
  if (name == "stop") return EndPolicy::stop;
  if (name == "wrap") return EndPolicy::wrap;
  return std::nullopt;
}

std::string_view to_string(ResetRule r) {
  switch (r) {
    case ResetRule::never: return "never";
    case ResetRule::midnight: return "midnight";
    case ResetRule::shift: return "shift";
  }
  return "?";
}

std::optional<ResetRule> parse_reset_rule(std::string_view name) {
  for (ResetRule r : {ResetRule::never, ResetRule::midnight, ResetRule::shift})
    if (name == to_string(r)) return r;
  return std::nullopt;
}

std::int64_t CounterSpec::effective_limit() const {
  if (limit) return *limit;
  return step > 0 ? alphabet.max_for_width(width) : 0;
}

bool CounterSpec::beyond(std::int64_t value) const {
  if (value < 0) return true;
  return step > 0 ? value > effective_limit() : value < effective_limit();
}

void CounterSpec::validate(std::string_view where) const {
  const std::string w(where);
  if (step == 0) throw InputError(w + ".step: a counter's step cannot be 0");
  if (marks_per_serial < 1)
    throw InputError(w + ".marks_per_serial: must be at least 1, got " + std::to_string(marks_per_serial));
  if (width < 0 || width > 64)
    throw InputError(w + ".width: must lie between 0 and 64 digits, got " + std::to_string(width));
  if (start < 0) throw InputError(w + ".start: a serial number cannot be negative, got " + std::to_string(start));
  const std::int64_t lim = effective_limit();
  if (lim < 0) throw InputError(w + ".limit: a serial number cannot be negative, got " + std::to_string(lim));
  if (step > 0 ? lim < start : lim > start)
    throw InputError(w + ".limit: " + std::to_string(lim) + " lies behind the start " +
                     std::to_string(start) + " for a step of " + std::to_string(step));
  const std::int64_t widest = std::max(lim, start);
  if (width > 0 && alphabet.digits(widest) > width)
    throw InputError(w + ".width: " + std::to_string(widest) + " needs " +
                     std::to_string(alphabet.digits(widest)) + " " + alphabet.name() +
                     " digits, the width is " + std::to_string(width) +
                     " (lower the limit or widen the field)");
}

CounterState CounterState::fresh(const CounterSpec& spec, std::string period) {
  CounterState s;
  s.next = spec.start;
  s.period = std::move(period);
  return s;
}

std::string period_key(const CounterSpec& spec, SysTime now, const ShiftTable& shifts) {
  switch (spec.reset) {
    case ResetRule::never: return "";
    case ResetRule::midnight: return local_date_key(spec.time_zone.local_seconds(now));
    case ResetRule::shift: return shifts.at(spec.time_zone.local_seconds(now)).key;
  }
  return "";
}

namespace {

// The start of a shift key "2026-03-05/C" as (date, minute of the day); nothing when the code is
// not in the table.
std::optional<std::pair<std::string, int>> shift_start(const std::string& key, const ShiftTable& shifts) {
  const std::size_t slash = key.find('/');
  if (slash == std::string::npos) return std::nullopt;
  const std::string code = key.substr(slash + 1);
  for (const Shift& s : shifts.shifts())
    if (s.code == code) return std::make_pair(key.substr(0, slash), s.start_minute);
  return std::nullopt;
}

}  // namespace

std::optional<SysTime> period_start(const CounterSpec& spec, const std::string& key, const ShiftTable& shifts) {
  std::string date = key;
  int minute = 0;
  if (spec.reset == ResetRule::shift) {
    const auto s = shift_start(key, shifts);
    if (!s) return std::nullopt;
    date = s->first;
    minute = s->second;
  } else if (spec.reset != ResetRule::midnight) {
    return std::nullopt;
  }
  int y = 0;
  unsigned m = 0, d = 0;
  if (date.size() != 10 || std::sscanf(date.c_str(), "%4d-%2u-%2u", &y, &m, &d) != 3) return std::nullopt;
  const date::year_month_day ymd{date::year{y}, date::month{m}, date::day{d}};
  if (!ymd.ok()) return std::nullopt;
  const std::chrono::seconds local = date::sys_days{ymd}.time_since_epoch() + std::chrono::minutes{minute};
  return spec.time_zone.from_local_seconds(local);
}

bool period_before(const CounterSpec& spec, const std::string& a, const std::string& b,
                   const ShiftTable& shifts) {
  if (a.empty() || b.empty()) return false;
  switch (spec.reset) {
    case ResetRule::never: return false;
    case ResetRule::midnight:
      // "YYYY-MM-DD": text order is date order; a key of the shift rule is not comparable.
      return a.size() == 10 && b.size() == 10 && a < b;
    case ResetRule::shift: {
      const auto sa = shift_start(a, shifts), sb = shift_start(b, shifts);
      return sa && sb && *sa < *sb;
    }
  }
  return false;
}

PeriodChoice current_period(const CounterSpec& spec, const CounterState& state, SysTime now,
                            const ShiftTable& shifts) {
  PeriodChoice c;
  c.clock_period = period_key(spec, now, shifts);
  c.period = c.clock_period;
  if (c.period != state.period && period_before(spec, c.period, state.period, shifts)) {
    c.period = state.period;
    c.stepped_back = true;
  }
  return c;
}

Issue take(const CounterSpec& spec, CounterState& state, const std::string& period) {
  CounterState s = state;
  if (s.period != period) s = CounterState::fresh(spec, period);
  if (s.exhausted || spec.beyond(s.next)) {
    if (spec.at_limit == EndPolicy::stop)
      throw SerialLimitError("counter '" + spec.name + "' has passed its limit " +
                             std::to_string(spec.effective_limit()) +
                             " (at_limit: stop); set it with `marker serial set` or change the job");
    const std::int64_t cycle = s.cycle + 1;
    s = CounterState::fresh(spec, period);
    s.cycle = cycle;
  }
  Issue issue{spec.name, s.next, s.used, s.period, s.cycle};
  if (++s.used >= spec.marks_per_serial) {
    s.used = 0;
    std::int64_t next = 0;
    if (__builtin_add_overflow(s.next, spec.step, &next))
      s.exhausted = true;  // past INT64_MAX: beyond any limit
    else
      s.next = next;
  }
  state = std::move(s);
  return issue;
}

std::optional<Issue> peek(const CounterSpec& spec, const CounterState& state,
                          const std::string& period) {
  CounterState copy = state;
  try {
    return take(spec, copy, period);
  } catch (const SerialLimitError&) {
    return std::nullopt;
  }
}

}  // namespace mark
