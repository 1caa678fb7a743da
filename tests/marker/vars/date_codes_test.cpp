// Date-code tables: the built-in VIN model-year characters as 49 CFR 565 lists them, ISO 8601
// week numbers at the year's edges (checked against the calendar), a job's own tables read and
// rendered, and a date the table lacks refused naming the table and the value.
#include "marker/vars/date_codes.hpp"

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "marker/production/job_file.hpp"
#include "marker/production/part_texts.hpp"
#include "marker/vars/check_digit.hpp"
#include "marker/vars/render.hpp"

namespace mark {
namespace {

std::tm day(int y, int m, int d, int h = 12) {
  std::tm tm{};
  tm.tm_year = y - 1900;
  tm.tm_mon = m - 1;
  tm.tm_mday = d;
  tm.tm_hour = h;
  const std::time_t t = timegm(&tm);  // fills in the weekday and day of the year
  gmtime_r(&t, &tm);
  return tm;
}

TEST(DateCodes, VinModelYearCharacters) {
  const DateCodeTable* vin = builtin_date_code_table("vin-year");
  ASSERT_TRUE(vin);
  // 49 CFR 565.15 Table VI: 1980 A, 1999 X, 2000 Y, 2001 1, 2009 9, 2010 A, 2025 S, 2026 T, 2030 Y.
  const std::vector<std::pair<int, std::string>> table = {{1980, "A"}, {1999, "X"}, {2000, "Y"}, {2001, "1"},
                                                          {2009, "9"}, {2010, "A"}, {2017, "H"}, {2018, "J"},
                                                          {2025, "S"}, {2026, "T"}, {2027, "V"}, {2030, "Y"}};
  for (const auto& [year, code] : table) EXPECT_EQ(date_code(*vin, "vin-year", day(year, 6, 1)), code) << year;
  EXPECT_FALSE(builtin_date_code_table("year"));
}

TEST(DateCodes, IsoWeeksAtTheYearsEdges) {
  EXPECT_EQ(date_unit_value(DateUnit::week, day(2026, 1, 1)), 1);    // a Thursday: week 1
  EXPECT_EQ(date_unit_value(DateUnit::week, day(2021, 1, 1)), 53);   // a Friday: 2020's week 53
  EXPECT_EQ(date_unit_value(DateUnit::week, day(2020, 12, 31)), 53);
  EXPECT_EQ(date_unit_value(DateUnit::week, day(2024, 12, 30)), 1);  // a Monday: 2025's week 1
  EXPECT_EQ(date_unit_value(DateUnit::week, day(2026, 11, 26)), 48);
  EXPECT_EQ(date_unit_value(DateUnit::weekday, day(2026, 11, 26)), 4);  // Thursday
  EXPECT_EQ(date_unit_value(DateUnit::weekday, day(2026, 11, 29)), 7);  // Sunday
  // Every day of 1990–2040 against strftime's %V (glibc's ISO week).
  std::tm from = day(1990, 1, 1), to = day(2041, 1, 1);
  for (std::time_t t = timegm(&from); t < timegm(&to); t += 86400) {
    std::tm tm{};
    gmtime_r(&t, &tm);
    char v[4];
    std::strftime(v, sizeof v, "%V", &tm);
    ASSERT_EQ(date_unit_value(DateUnit::week, tm), std::stoi(v)) << std::asctime(&tm);
  }
}

constexpr const char* kJob = R"({"format": "marker-job/1", "head": "SL10", "time_zone": "UTC",
  "counters": {"sn": {"start": 41, "width": 4}}, "pens": {"p": {}},
  "date_codes": {"year": {"unit": "year", "codes": {"2026": "T", "2027": "V"}},
                 "month": {"unit": "month", "codes": ["A", "B", "C", "D", "E", "F", "G", "H", "J", "K", "L", "M"]}},
  "objects": [{"name": "t", "template": "{datecode:year}{datecode:month}{date:%d}-{sn}{check:iso7064-37-36} {datecode:vin-year}"}]})";

std::string job_error(const std::string& text) {
  try {
    parse_job(text, "j.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  return s.replace(s.find(from), from.size(), to);
}

TEST(DateCodes, AJobsTablesRenderAndADateTheyLackIsRefused) {
  const JobFile job = parse_job(kJob, "j.json");
  const std::map<std::string, std::int64_t> serials{{"sn", 41}};
  const auto at = [](int y, int m, int d) {
    std::tm tm = day(y, m, d);
    return SysTime(std::chrono::seconds(timegm(&tm)));
  };
  const std::vector<ObjectText> t = render_objects(job, {}, at(2026, 11, 26), serials, nullptr);
  // November is the 11th code, L; the check covers "TL26-0041".
  const char check = check_character(CheckDigit::iso7064_37_36, "TL26-0041");
  EXPECT_EQ(t.at(0).text, std::string("TL26-0041") + check + " T");
  try {
    render_objects(job, {}, at(2028, 1, 5), serials, nullptr);
    FAIL() << "2028 has no year code";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "j.json: objects[0] \"t\": {datecode:year}: the table has no code for year 2028; add it to the job's \"date_codes\"");
  }
  EXPECT_EQ(job_error(replaced(kJob, "{datecode:year}", "{datecode:yr}")),
            "j.json: objects[0].template: {datecode:yr}: no table named \"yr\" in \"date_codes\" (built in: vin-year)");
  EXPECT_EQ(job_error(replaced(kJob, R"("unit": "month")", R"("unit": "moon")")),
            "j.json: date_codes.month.unit: expected one of year, month, day, week, weekday, hour");
  EXPECT_EQ(job_error(replaced(kJob, R"("2027": "V")", R"("20x7": "V")")),
            "j.json: date_codes.year.codes: \"20x7\" is not a year (1 to 9999)");
  EXPECT_EQ(job_error(replaced(kJob, R"("year": {"unit")", R"("vin-year": {"unit")")),
            "j.json: date_codes.vin-year: \"vin-year\" is a built-in table; call yours something else");
}

}  // namespace
}  // namespace mark
