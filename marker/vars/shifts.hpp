#pragma once
// Shift codes from shift start times: {"A", 06:00}, {"B", 14:00}, {"C", 22:00} means A runs
// 06:00–14:00, B 14:00–22:00 and C from 22:00 to 06:00 the next morning (the night shift
// belongs to the day it started). Times are wall-clock times in the job's time zone.
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

namespace mark {

struct Shift {
  std::string code;
  int start_minute = 0;  // minutes after local midnight, 0..1439
};

// Where a local time falls: the shift, the local midnight of the day it started (seconds since
// the local epoch) and a key naming that shift occurrence ("2026-03-05/C").
struct ShiftInstant {
  const Shift* shift = nullptr;
  std::chrono::seconds day_local{0};
  std::string key;
};

class ShiftTable {
 public:
  ShiftTable() = default;
  // Throws InputError when empty, a code is empty, or two shifts start at the same time.
  explicit ShiftTable(std::vector<Shift> shifts);

  bool empty() const { return shifts_.empty(); }
  const std::vector<Shift>& shifts() const { return shifts_; }  // sorted by start
  // Throws InputError when the table is empty.
  ShiftInstant at(std::chrono::seconds local) const;

 private:
  std::vector<Shift> shifts_;
};

// "06:00" → 360; throws InputError("<what>: ...") unless HH:MM with HH 00..23, MM 00..59.
int parse_clock_time(std::string_view hh_mm, std::string_view what);
std::string format_clock_time(int minute);
// "2026-03-05" for the day holding local second `local`.
std::string local_date_key(std::chrono::seconds local);

}  // namespace mark
