#pragma once
// A time zone for dates, shift codes and counter resets: "local" (the machine's zone), "UTC",
// or an IANA name ("Europe/Berlin") from the system's tz database, through Howard Hinnant's
// date/tz library (what became C++20's <chrono> time zones; GCC 12 lacks them).
#include <ctime>
#include <string>
#include <string_view>

#include "marker/vars/clock.hpp"

namespace date {
class time_zone;
}

namespace mark {

class TimeZone {
 public:
  // UTC.
  TimeZone();
  // "local", "UTC" or an IANA name; throws InputError naming the zone otherwise.
  static TimeZone named(std::string_view name);

  // The name as given ("local" stays "local"; its zone is the machine's at lookup time).
  const std::string& name() const { return name_; }
  // Local wall-clock time at `t`, as seconds since 1970-01-01 00:00 local.
  std::chrono::seconds local_seconds(SysTime t) const;
  // Broken-down local time at `t` for strftime (tm_zone points into the zone's abbreviation
  // storage, valid as long as the returned `abbrev` string it is given).
  std::tm local_tm(SysTime t, std::string& abbrev) const;
  // The instant a local wall-clock time names (a time skipped by a DST change maps to the
  // instant after the gap, an ambiguous one to the earlier instant).
  SysTime from_local_seconds(std::chrono::seconds local) const;

 private:
  std::string name_ = "UTC";
  const date::time_zone* zone_ = nullptr;  // nullptr: UTC
};

}  // namespace mark
