// Templates: every field type, padding modes, alphabets, rendering with fixed clocks, and the
// one-line errors of malformed templates.
#include <gtest/gtest.h>

#include <date/date.h>

#include "marker/vars/render.hpp"
#include "tests/marker/vars/at_utc.hpp"

namespace mark {
namespace {

using namespace std::chrono;

using test::at_utc;

struct Fixture {
  std::map<std::string, CounterSpec> counters;
  std::map<std::string, std::int64_t> serials;
  std::map<std::string, std::string> variables;
  ShiftTable shifts{{{"A", 6 * 60}, {"B", 14 * 60}, {"C", 22 * 60}}};
  TimeZone zone = TimeZone::named("UTC");
  SysTime now = at_utc(2026, 3, 5, 9, 41);

  Fixture() {
    CounterSpec s;
    s.name = "serial";
    s.width = 6;
    counters["serial"] = s;
    serials["serial"] = 42;
  }
  std::string operator()(std::string_view source) {
    MarkValues v;
    v.now = now;
    v.zone = &zone;
    v.shifts = &shifts;
    v.variables = &variables;
    v.counters = &counters;
    v.serials = &serials;
    return render(TextTemplate::parse(source, "test"), v);
  }
};

std::string parse_error(std::string_view source) {
  try {
    TextTemplate::parse(source, "objects[0].template");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(Template, CounterWithItsOwnFormatting) {
  Fixture f;
  EXPECT_EQ(f("SN {serial}"), "SN 000042");
}

TEST(Template, PaddingModesAsRtcMarkSerial) {
  Fixture f;
  EXPECT_EQ(f("[{serial:keep}]"), "[000042]");
  EXPECT_EQ(f("[{serial:suppress}]"), "[42]");
  EXPECT_EQ(f("[{serial:blank}]"), "[    42]");
  EXPECT_EQ(f("[{serial:3:blank}]"), "[ 42]");
}

TEST(Template, Alphabets) {
  Fixture f;
  f.serials["serial"] = 35;
  EXPECT_EQ(f("{serial:base36:8}"), "0000000Z");
  EXPECT_EQ(f("{serial:hex:4}"), "0023");
  EXPECT_EQ(f("{serial:decimal:2}"), "35");
  // Base 36 without I, O and Q: 18 is 'J' (I skipped), 23 is 'P' (O skipped), 24 is 'R' (Q).
  f.serials["serial"] = 18;
  EXPECT_EQ(f("{serial:base33:1}"), "J");
  f.serials["serial"] = 23;
  EXPECT_EQ(f("{serial:base33:1}"), "P");
  f.serials["serial"] = 24;
  EXPECT_EQ(f("{serial:base33:1}"), "R");
  f.serials["serial"] = 33 * 33 - 1;
  EXPECT_EQ(f("{serial:base33:2}"), "ZZ");
  f.counters["serial"].alphabet = Alphabet::custom("αβγ", "test");
  f.serials["serial"] = 5;  // 12 in base 3
  EXPECT_EQ(f("{serial:3}"), "αβγ");
}

TEST(Template, LargestSixtyFourBitValue) {
  Fixture f;
  f.serials["serial"] = INT64_MAX;
  EXPECT_EQ(f("{serial:suppress}"), "9223372036854775807");
  EXPECT_EQ(f("{serial:hex:1}"), "7FFFFFFFFFFFFFFF");
}

TEST(Template, DateInTheGivenTimeZone) {
  Fixture f;
  EXPECT_EQ(f("{date}"), "2026-03-05");
  EXPECT_EQ(f("{date:%y%j}"), "26064");
  EXPECT_EQ(f("{date:%H:%M %Z}"), "09:41 UTC");
  f.zone = TimeZone::named("Asia/Tokyo");
  EXPECT_EQ(f("{date:%Y-%m-%d %H:%M %z}"), "2026-03-05 18:41 +0900");
  f.now = at_utc(2026, 12, 31, 16, 0);  // 01:00 on 1 January in Tokyo
  EXPECT_EQ(f("{date:%y%j %a}"), "27001 Fri");
}

TEST(Template, ShiftCodes) {
  Fixture f;
  EXPECT_EQ(f("{shift}"), "A");
  f.now = at_utc(2026, 3, 5, 14, 0);
  EXPECT_EQ(f("{shift}"), "B");
  f.now = at_utc(2026, 3, 6, 3, 0);
  EXPECT_EQ(f("{shift}"), "C");
}

TEST(Template, VariablesAndBraces) {
  Fixture f;
  f.variables["lot"] = "A17";
  EXPECT_EQ(f("LOT {var:lot} {{x}}"), "LOT A17 {x}");
  try {
    f("{var:batch}");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "{var:batch} has no value: set it with --set batch=VALUE");
  }
}

TEST(Template, MixedTwentyCharacterSerial) {
  Fixture f;
  f.variables["lot"] = "A17";
  f.serials["serial"] = 4711;
  EXPECT_EQ(f("{var:lot}-{date:%y%j}{shift}-{serial:8}"), "A17-26064A-00004711");
}

TEST(Template, NamesWhatItUses) {
  const TextTemplate t = TextTemplate::parse("{a}{b:hex}{a}{var:x}{date}", "t");
  EXPECT_EQ(t.counters(), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(t.variables(), (std::vector<std::string>{"x"}));
  EXPECT_TRUE(t.uses(FieldKind::date));
  EXPECT_FALSE(t.uses(FieldKind::shift));
  EXPECT_FALSE(t.constant());
  EXPECT_TRUE(TextTemplate::parse("ACME {{}}", "t").constant());
}

TEST(Template, MalformedTemplatesGiveOneLineErrors) {
  EXPECT_EQ(parse_error("SN {serial"),
            "objects[0].template: 'SN {serial' at character 4: '{' without a closing '}'");
  EXPECT_EQ(parse_error("SN }"),
            "objects[0].template: 'SN }' at character 4: a lone '}' (write }} for a literal brace)");
  EXPECT_EQ(parse_error("{serial:base37}"),
            "objects[0].template: '{serial:base37}' at character 1: 'base37' is not an alphabet "
            "(decimal, hex, base36, base33), a width (1..64) or a padding (keep, suppress, blank)");
  EXPECT_EQ(parse_error("{serial:0}"),
            "objects[0].template: '{serial:0}' at character 1: width '0' is not a number of "
            "digits from 1 to 64");
  EXPECT_EQ(parse_error("{serial:8:9}"),
            "objects[0].template: '{serial:8:9}' at character 1: two widths in one field");
  EXPECT_EQ(parse_error("{date:%Q}").substr(0, 68),
            "objects[0].template: '{date:%Q}' at character 1: '%Q' is not a date ");
  EXPECT_EQ(parse_error("{date:%}"),
            "objects[0].template: '{date:%}' at character 1: the date format ends with a lone '%'");
  EXPECT_EQ(parse_error("{var:}"),
            "objects[0].template: '{var:}' at character 1: {var:NAME} needs a name of letters, "
            "digits, _ - or .");
  EXPECT_EQ(parse_error("{shift:x}"),
            "objects[0].template: '{shift:x}' at character 1: {shift} takes no options");
  EXPECT_EQ(parse_error("{}").substr(0, 55),
            "objects[0].template: '{}' at character 1: '{}' is not a");
  EXPECT_EQ(parse_error("{a{b}}"),
            "objects[0].template: '{a{b}}' at character 1: a '{' inside a field");
}

TEST(Alphabet, CustomAlphabetsAreChecked) {
  EXPECT_THROW(Alphabet::custom("0", "a"), InputError);
  EXPECT_THROW(Alphabet::custom("0120", "a"), InputError);
  EXPECT_THROW(Alphabet::custom("01 ", "a"), InputError);
  EXPECT_THROW(Alphabet::custom("\xff\xfe", "a"), InputError);
  const Alphabet a = Alphabet::custom("XY", "a");
  EXPECT_EQ(a.format(5), "YXY");
  EXPECT_EQ(a.max_for_width(3), 7);
  EXPECT_EQ(a.digits(0), 1);
}

TEST(TimeZoneLookup, UnknownZoneIsAnError) {
  try {
    TimeZone::named("Mars/Olympus");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "time zone 'Mars/Olympus' is not known (use local, UTC or a name like "
                 "Europe/Berlin from the system's tz database)");
  }
  EXPECT_EQ(TimeZone::named("local").name(), "local");
}

TEST(TimeZoneLookup, LocalTimesAcrossDaylightSaving) {
  const TimeZone berlin = TimeZone::named("Europe/Berlin");
  // 29 March 2026, 02:30 does not exist in Berlin (clocks jump 02:00 → 03:00 = 01:00 UTC).
  const std::chrono::seconds gap = (date::sys_days{date::year{2026} / 3 / 29}).time_since_epoch() +
                                   hours{2} + minutes{30};
  EXPECT_EQ(berlin.from_local_seconds(gap), at_utc(2026, 3, 29, 1, 0));
  const std::chrono::seconds noon = (date::sys_days{date::year{2026} / 7 / 1}).time_since_epoch() + hours{12};
  EXPECT_EQ(berlin.from_local_seconds(noon), at_utc(2026, 7, 1, 10, 0));
}

}  // namespace
}  // namespace mark
