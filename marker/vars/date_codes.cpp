#include "marker/vars/date_codes.hpp"

#include <array>

#include "base/error.hpp"

namespace mark {
namespace {

struct Unit {
  DateUnit unit;
  std::string_view name;
  int first, last;
};
constexpr std::array<Unit, 6> kUnits{{{DateUnit::year, "year", 0, 0},
                                      {DateUnit::month, "month", 1, 12},
                                      {DateUnit::day, "day", 1, 31},
                                      {DateUnit::week, "week", 1, 53},
                                      {DateUnit::weekday, "weekday", 1, 7},
                                      {DateUnit::hour, "hour", 0, 23}}};

const Unit& unit_of(DateUnit u) {
  for (const Unit& x : kUnits)
    if (x.unit == u) return x;
  return kUnits.front();
}

DateCodeTable vin_years() {
  // 49 CFR 565.15(c), Table VI: the 30 characters in order, from 1980.
  static constexpr std::string_view kCycle = "ABCDEFGHJKLMNPRSTVWXY123456789";
  DateCodeTable t;
  t.unit = DateUnit::year;
  for (int y = 1980; y <= 2099; ++y) t.codes[y] = std::string(1, kCycle[static_cast<std::size_t>(y - 1980) % kCycle.size()]);
  return t;
}

// ISO 8601 week number of a date (tm_yday 0-based, tm_wday 0 Sunday).
int iso_week(const std::tm& tm) {
  const int wday = tm.tm_wday == 0 ? 7 : tm.tm_wday;
  const int week = (tm.tm_yday + 1 - wday + 10) / 7;
  const auto weeks_in = [](int year) {
    // A year has 53 ISO weeks when 1 January is a Thursday, or a Wednesday in a leap year.
    const auto jan1 = [](int y) {  // weekday of 1 January, 1 Monday … 7 Sunday (Gauss)
      const int c = (1 + 5 * ((y - 1) % 4) + 4 * ((y - 1) % 100) + 6 * ((y - 1) % 400)) % 7;
      return c == 0 ? 7 : c;
    };
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return jan1(year) == 4 || (leap && jan1(year) == 3) ? 53 : 52;
  };
  const int year = tm.tm_year + 1900;
  if (week < 1) return weeks_in(year - 1);
  if (week > weeks_in(year)) return 1;
  return week;
}

}  // namespace

std::optional<DateUnit> parse_date_unit(std::string_view name) {
  for (const Unit& u : kUnits)
    if (u.name == name) return u.unit;
  return std::nullopt;
}

std::string_view to_string(DateUnit u) { return unit_of(u).name; }

std::string date_unit_names() {
  std::string s;
  for (const Unit& u : kUnits) s += (s.empty() ? "" : ", ") + std::string(u.name);
  return s;
}

int first_value(DateUnit u) { return unit_of(u).first; }
int last_value(DateUnit u) { return unit_of(u).last; }

const DateCodeTable* builtin_date_code_table(std::string_view name) {
  static const DateCodeTable kVinYear = vin_years();
  return name == "vin-year" ? &kVinYear : nullptr;
}

int date_unit_value(DateUnit u, const std::tm& tm) {
  switch (u) {
    case DateUnit::year: return tm.tm_year + 1900;
    case DateUnit::month: return tm.tm_mon + 1;
    case DateUnit::day: return tm.tm_mday;
    case DateUnit::week: return iso_week(tm);
    case DateUnit::weekday: return tm.tm_wday == 0 ? 7 : tm.tm_wday;
    case DateUnit::hour: return tm.tm_hour;
  }
  return 0;
}

const std::string& date_code(const DateCodeTable& table, std::string_view name, const std::tm& tm) {
  const int value = date_unit_value(table.unit, tm);
  const auto it = table.codes.find(value);
  if (it == table.codes.end())
    throw InputError("{datecode:" + std::string(name) + "}: the table has no code for " +
                     std::string(to_string(table.unit)) + " " + std::to_string(value) +
                     "; add it to the job's \"date_codes\"");
  return it->second;
}

}  // namespace mark
