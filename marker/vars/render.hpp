#pragma once
// One part's text from a template: the counter values this part consumed, the clock, the
// variables set from outside, the shift table.
#include <cstdint>
#include <map>
#include <string>

#include "marker/vars/counter.hpp"
#include "marker/vars/date_codes.hpp"
#include "marker/vars/shifts.hpp"
#include "marker/vars/text_template.hpp"
#include "marker/vars/time_zone.hpp"

namespace mark {

struct MarkValues {
  SysTime now{};
  const TimeZone* zone = nullptr;  // dates and shifts (nullptr: UTC)
  const ShiftTable* shifts = nullptr;
  const std::map<std::string, std::string>* variables = nullptr;
  const std::map<std::string, CounterSpec>* counters = nullptr;
  const std::map<std::string, std::int64_t>* serials = nullptr;  // values this part consumed
  const std::map<std::string, std::string>* columns = nullptr;   // the part's data-list row
  const std::map<std::string, DateCodeTable>* date_codes = nullptr;  // the job's; built-ins besides
};

// Appends the rendered text to `out`. Throws InputError naming the field for a variable that
// was not set, a counter without a value, {shift} without shifts, a date a date-code table has
// no code for, or a character a check cannot take. Check characters are computed last, over the
// text rendered before them (from the template's start or the previous check).
void render(const TextTemplate& t, const MarkValues& values, std::string& out);
inline std::string render(const TextTemplate& t, const MarkValues& values) {
  std::string s;
  render(t, values, s);
  return s;
}

}  // namespace mark
