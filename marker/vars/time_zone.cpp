#include "marker/vars/time_zone.hpp"

#include <date/tz.h>

#include "base/error.hpp"

namespace mark {

using namespace std::chrono;

TimeZone::TimeZone() = default;

TimeZone TimeZone::named(std::string_view name) {
  TimeZone z;
  z.name_ = std::string(name);
  if (name == "UTC" || name == "utc" || name == "Etc/UTC") return z;
  try {
    if (name == "local") {
      z.zone_ = date::current_zone();
    } else {
      z.zone_ = date::locate_zone(std::string(name));
    }
  } catch (const std::exception& e) {
    if (name == "local") {
      // A machine without /etc/localtime (a bare container) keeps its clocks in UTC.
      z.zone_ = nullptr;
      return z;
    }
    throw InputError("time zone '" + std::string(name) +
                     "' is not known (use local, UTC or a name like Europe/Berlin from the "
                     "system's tz database)");
  }
  return z;
}

seconds TimeZone::local_seconds(SysTime t) const {
  const sys_seconds s = floor<seconds>(t);
  if (!zone_) return s.time_since_epoch();
  const date::sys_info info = zone_->get_info(s);
  return s.time_since_epoch() + info.offset;
}

std::tm TimeZone::local_tm(SysTime t, std::string& abbrev) const {
  const sys_seconds s = floor<seconds>(t);
  seconds offset{0};
  abbrev = "UTC";
  if (zone_) {
    const date::sys_info info = zone_->get_info(s);
    offset = info.offset;
    abbrev = info.abbrev;
  }
  const seconds local = s.time_since_epoch() + offset;
  const date::sys_days day{floor<date::days>(local)};
  const date::year_month_day ymd{day};
  const date::hh_mm_ss<seconds> hms{local - floor<date::days>(local)};
  const date::weekday wd{day};
  const date::sys_days jan1 = date::sys_days{ymd.year() / date::January / 1};
  std::tm tm{};
  tm.tm_year = int(ymd.year()) - 1900;
  tm.tm_mon = static_cast<int>(unsigned(ymd.month())) - 1;
  tm.tm_mday = static_cast<int>(unsigned(ymd.day()));
  tm.tm_hour = static_cast<int>(hms.hours().count());
  tm.tm_min = static_cast<int>(hms.minutes().count());
  tm.tm_sec = static_cast<int>(hms.seconds().count());
  tm.tm_wday = static_cast<int>(wd.c_encoding());
  tm.tm_yday = static_cast<int>((day - jan1).count());
  tm.tm_isdst = 0;
  tm.tm_gmtoff = offset.count();
  tm.tm_zone = abbrev.c_str();
  return tm;
}

SysTime TimeZone::from_local_seconds(seconds local) const {
  const date::local_seconds ls{local};
  if (!zone_) return SysTime{duration_cast<microseconds>(local)};
  const date::local_info info = zone_->get_info(ls);
  seconds offset = info.first.offset;
  if (info.result == date::local_info::nonexistent) {
    // Inside a spring-forward gap: the wall clock jumps past it; take the instant it ends.
    return SysTime{duration_cast<microseconds>(info.second.begin.time_since_epoch())};
  }
  return SysTime{duration_cast<microseconds>(local - offset)};
}

}  // namespace mark
