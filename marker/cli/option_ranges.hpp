#pragma once
// Every option of `marker` that is a setting is registered from its one declaration in
// marker/limits/ (add_setting): its help, its default and its range or choices. A value outside
// its range is refused with one line naming the option, the value as typed and the range
// ("--angle: 1e20 is outside the range -360 to 360 degrees"), never clipped or passed on to give
// a nonsense result. Ranges fixed at build time are checked while the command line is parsed (a
// CLI11 validator, shown in --help); ranges that depend on other options (--x within the field,
// --pitch no finer than a motor step) are checked after parsing with the same function and the
// same wording.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "marker/limits/setting.hpp"
#include "marker/limits/value_range.hpp"

namespace mark::cli {

// mark::check_range (value_range.hpp) names the option; this overload skips an option not given.
using mark::check_range;
inline void check_range(std::string_view option, const std::optional<double>& v, const Range& range) {
  if (v) check_range(option, *v, range);
}

// A setting's flag with the prefix after its dashes: "--module" → "--code-module".
std::string flag_of(const SettingName& n, std::string_view prefix = {});

// The option of a setting (marker/limits/setting.hpp): its flag (after `prefix`: "code-" turns
// --module into --code-module), its help with its range and its default in words, its range or
// choices checked while parsing. The value starts at the setting's default where it has one.
CLI::Option* add_setting(CLI::App& app, const Quantity& s, double& value, std::string_view prefix = {});
CLI::Option* add_setting(CLI::App& app, const Quantity& s, std::optional<double>& value, std::string_view prefix = {});
// A comma-separated list of numbers, each within the range.
CLI::Option* add_setting(CLI::App& app, const Quantity& s, std::vector<double>& values, std::string_view prefix = {});
CLI::Option* add_setting(CLI::App& app, const Count& s, int& value, std::string_view prefix = {});
CLI::Option* add_setting(CLI::App& app, const Count& s, long long& value, std::string_view prefix = {});
CLI::Option* add_setting(CLI::App& app, const Count& s, std::optional<long long>& value, std::string_view prefix = {});
CLI::Option* add_setting(CLI::App& app, const Choice& s, std::string& value, std::string_view prefix = {});
CLI::Option* add_setting(CLI::App& app, const Toggle& s, bool& value, std::string_view prefix = {});
CLI::Option* add_setting(CLI::App& app, const Text& s, std::string& value, std::string_view prefix = {});
// Text where given-but-empty differs from not given (`log --text ""`).
CLI::Option* add_setting(CLI::App& app, const Text& s, std::optional<std::string>& value);
// Repeatable text (--set NAME=VALUE …).
CLI::Option* add_setting(CLI::App& app, const Text& s, std::vector<std::string>& values);
// A setting whose range also depends on the head (a speed at most its positioning limit, the
// tick at most 20 % of its τ: head_speed_range, head_tick_range in marker/job/head_pen.hpp). While
// parsing only a number is required; the range is checked once, against the head, where the head
// is known (make_pen), so the command line refuses it in the words a job file does
// ("--jump-speed: 0.5 is outside the range 1 to 19200 mm/s (head SL10's positioning limit)").
CLI::Option* add_head_limited_setting(CLI::App& app, const Quantity& s, double& value);
CLI::Option* add_head_limited_setting(CLI::App& app, const Quantity& s, std::optional<double>& value);
// A head-limited number (as above), or `word` ("auto", explained by `word_help`); the value is
// kept as typed (number_or_word() reads it) and starts as `word`.
CLI::Option* add_setting(CLI::App& app, const Quantity& s, std::string& value, std::string_view word,
                         std::string_view word_help);
// The number of such an option, or nothing for the word; throws InputError naming the option
// for anything else and for a number outside `range` (the setting's, narrowed by the head).
std::optional<double> number_or_word(const Quantity& s, const std::string& value, std::string_view word,
                                     const Range& range);

// A setting's option, for messages: flag(kHeight) == "--height".
template <class S>
std::string flag(const S& setting) {
  return std::string(setting.name.flag);
}

// The description add_setting gives a setting's option (the settings test compares them).
std::string setting_description(const SettingRef& s);

// The range an option was registered with (for the documentation test); nullopt for an option
// without one.
std::optional<std::string> registered_range(const CLI::Option& option);

}  // namespace mark::cli
