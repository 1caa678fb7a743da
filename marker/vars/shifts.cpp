#include "marker/vars/shifts.hpp"

#include <date/date.h>

#include <algorithm>
#include <cstdio>

#include "base/error.hpp"

namespace mark {

using namespace std::chrono;

ShiftTable::ShiftTable(std::vector<Shift> shifts) : shifts_(std::move(shifts)) {
  if (shifts_.empty()) throw InputError("a shift table needs at least one shift");
  std::sort(shifts_.begin(), shifts_.end(),
            [](const Shift& a, const Shift& b) { return a.start_minute < b.start_minute; });
  for (std::size_t i = 0; i < shifts_.size(); ++i) {
    if (shifts_[i].code.empty()) throw InputError("a shift needs a code");
    if (shifts_[i].start_minute < 0 || shifts_[i].start_minute >= 24 * 60)
      throw InputError("shift '" + shifts_[i].code + "' starts outside 00:00..23:59");
    if (i > 0 && shifts_[i].start_minute == shifts_[i - 1].start_minute)
      throw InputError("shifts '" + shifts_[i - 1].code + "' and '" + shifts_[i].code +
                       "' both start at " + format_clock_time(shifts_[i].start_minute));
  }
}

ShiftInstant ShiftTable::at(seconds local) const {
  if (shifts_.empty()) throw InputError("the job has no shifts, so {shift} has no value");
  const seconds day = floor<date::days>(local);
  const int minute = static_cast<int>(duration_cast<minutes>(local - day).count());
  ShiftInstant s;
  s.day_local = day;
  // The last shift starting at or before this minute; before the first start it is the last
  // shift of the previous day (the night shift).
  auto it = std::upper_bound(shifts_.begin(), shifts_.end(), minute,
                             [](int m, const Shift& sh) { return m < sh.start_minute; });
  if (it == shifts_.begin()) {
    s.shift = &shifts_.back();
    s.day_local = day - date::days{1};
  } else {
    s.shift = &*(it - 1);
  }
  s.key = local_date_key(s.day_local) + "/" + s.shift->code;
  return s;
}

int parse_clock_time(std::string_view t, std::string_view what) {
  auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (t.size() != 5 || !digit(t[0]) || !digit(t[1]) || t[2] != ':' || !digit(t[3]) || !digit(t[4]))
    throw InputError(std::string(what) + ": '" + std::string(t) + "' is not a time HH:MM");
  const int h = (t[0] - '0') * 10 + (t[1] - '0');
  const int m = (t[3] - '0') * 10 + (t[4] - '0');
  if (h > 23 || m > 59)
    throw InputError(std::string(what) + ": '" + std::string(t) +
                     "' is not a time of day (00:00 to 23:59)");
  return h * 60 + m;
}

std::string format_clock_time(int minute) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02d:%02d", (minute / 60) % 100, minute % 60);
  return buf;
}

std::string local_date_key(seconds local) {
  const date::year_month_day ymd{date::sys_days{floor<date::days>(local)}};
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02u", int(ymd.year()), unsigned(ymd.month()),
                unsigned(ymd.day()));
  return buf;
}

}  // namespace mark
