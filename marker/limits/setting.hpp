#pragma once
// One declaration per user-facing setting (as Klipper declares each command once beside its
// handler): its command-line option, its job-file key, its range or choices, its default and
// its help. The command line registers its options from these declarations
// (marker/cli/option_ranges.hpp), the job-file reader reads its keys through them
// (marker/production/json_reader.hpp), `marker job new` writes its keys by them, and the docs'
// option tables are printed from them (`marker options --markdown TABLE`), so a range, a default
// or a wording cannot differ between the two ways of giving a setting or between code and docs.
//
// Every setting is a compile-time constant (literal types, string views): no static
// initialisation order can see one half-made, and library structs may take their defaults from
// them. The tables that list them for the docs are in the *_settings.hpp headers beside them.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "marker/limits/value_range.hpp"

namespace mark {

// Where a setting is given and what it means.
struct SettingName {
  std::string_view flag;  // command-line option, "--speed" (empty: job files only)
  std::string_view key;   // job-file key relative to its table's place, "speed_mm_s" (empty: command line only)
  std::string_view help;  // what it is; the range (and a derived default) are added where it is shown
};

// A number's bounds as a table declares them; range() is the value_range.hpp Range.
struct Bounds {
  double min = 0;
  double max = 0;
  std::string_view unit;        // "mm", "mm/s", "degrees", … (empty: a plain factor)
  bool above_min = false;       // min itself is excluded
  bool zero_means = false;      // 0 is also accepted (a documented "off" or "automatic")
  Range range() const { return Range{min, max, std::string(unit), above_min, zero_means}; }
};

// A number with a unit and a range.
struct Quantity {
  SettingName name;
  Bounds bounds;
  std::optional<double> value = {};  // the default (none: there is none, or it depends on other settings)
  // The default in words, shown instead of `value` where it needs them: one that depends on
  // other settings ("half the head's positioning limit"), or that differs by command.
  std::string_view derived = {};
  Range range() const { return bounds.range(); }
  // The default; a setting without one must not be asked (a programming error: throws logic_error).
  double fallback() const;
};

// A whole number.
struct Count {
  SettingName name;
  WholeRange range;
  std::optional<std::int64_t> value = {};
  std::string_view derived = {};  // as Quantity's
  std::int64_t fallback() const;
};

// One of a few names.
struct Choice {
  SettingName name;
  std::string_view choices;  // "blanking, delays, none"
  std::string_view value = {};  // the default (empty: none, or `derived` says what applies)
  std::string_view derived = {};  // as Quantity's
  std::vector<std::string> names() const;
  bool allows(std::string_view name) const;
};

// On or off: off unless given, or (`on`) on unless turned off with its --no- form.
struct Toggle {
  SettingName name;
  bool on = false;
};

// Free text: a font name, a template, a time zone.
struct Text {
  SettingName name;
  std::string_view value = {};  // the default (empty: none, or `derived` says what applies)
  std::string_view derived = {};  // as Quantity's
};

using SettingRef = std::variant<const Quantity*, const Count*, const Choice*, const Toggle*, const Text*>;

const SettingName& name_of(const SettingRef& s);
// As shown in a table's "range" column: "0.001 to 100000 mm/s", "1 to 100", "`blanking`,
// `delays`, `none`", "on or off", "text".
std::string range_text(const SettingRef& s);
// As shown in a table's "default" column: "1000", "`blanking`", "the head's", "off", "—".
std::string default_text(const SettingRef& s);

// A table of settings: what one part of the product takes, shown as one table in the docs.
struct SettingTable {
  std::string_view id;     // `marker options ID`, and the docs' <!-- settings: ID --> marker
  std::string_view title;  // "Pen"
  // Where its keys live in a job file, as a path: "pens.NAME" (NAME: any name), "objects[]"
  // (any index), several separated by ", "; empty: the top level. A key with a dot in it
  // ("circle.cx_mm") is relative to it.
  std::string_view place;
  std::span<const SettingRef> settings;
};

// Throws InputError "NAME: VALUE is outside the range RANGE" (value_range.hpp's check_range)
// with the setting's flag as the name.
void check_setting(const Quantity& s, double v);

// A range that also depends on something only known later (the head's positioning limit, the
// field): the setting's own lower end and unit, the upper end at most `max`, and `why` after the
// unit: "0.001 to 19200 mm/s (head SL10's positioning limit)".
Range limited_range(const Quantity& s, double max, std::string_view why);

}  // namespace mark
