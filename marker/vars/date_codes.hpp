#pragma once
// Date-code tables ({datecode:NAME}): the letters automotive and electronics part marking uses
// for the year, month, day, week, weekday or hour of manufacture (a year letter that cycles, a
// month letter skipping I and O), as the job file defines them ("date_codes") or built in:
//
//   vin-year   the model-year character of ISO 3779 / 49 CFR 565 (VIN position 10): 1980 A …
//              2000 Y, 2001 1 … 2009 9, 2010 A again (30-year cycle; I O Q U Z and 0 unused)
//
// A date the table has no code for is an error naming the table and the value (the part is
// refused, nothing consumed), never an empty or stale letter.
#include <ctime>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace mark {

enum class DateUnit { year, month, day, week, weekday, hour };

struct DateCodeTable {
  DateUnit unit = DateUnit::year;
  std::map<int, std::string> codes;  // unit value → code
};

std::optional<DateUnit> parse_date_unit(std::string_view name);
std::string_view to_string(DateUnit u);
// "year, month, day, week, weekday, hour"
std::string date_unit_names();
// The unit's values, for a table given as a list (the first value takes the first code);
// a year has no bounded range (a list needs "first").
int first_value(DateUnit u);
int last_value(DateUnit u);

// The built-in table of that name, or nothing.
const DateCodeTable* builtin_date_code_table(std::string_view name);

// The unit's value at local time `tm` (a year: 2026; month 1–12; day 1–31; ISO week 1–53;
// ISO weekday 1 Monday … 7 Sunday; hour 0–23).
int date_unit_value(DateUnit u, const std::tm& tm);

// The code of `table` (called `name`, for messages) at local time `tm`.
const std::string& date_code(const DateCodeTable& table, std::string_view name, const std::tm& tm);

}  // namespace mark
