#pragma once
// Every numeric option of `marker` has a documented range. A value outside it is refused with one
// line naming the option, the value as typed and the range ("--angle: 1e20 is outside the range
// -360 to 360 degrees"), never clipped or passed on to give a nonsense result. Ranges fixed at
// build time are checked while the command line is parsed (a CLI11 validator, shown in --help);
// ranges that depend on other options (--x within the field, --pitch no finer than a motor step)
// are checked after parsing with the same function and the same wording.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "marker/limits/value_range.hpp"

namespace mark::cli {

// mark::check_range (value_range.hpp) names the option; this overload skips an option not given.
using mark::check_range;
inline void check_range(std::string_view option, const std::optional<double>& v, const Range& range) {
  if (v) check_range(option, *v, range);
}

// Adds a numeric option whose value is checked against `range` while parsing; --help shows the
// range after the description.
CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, double& value,
                               const std::string& description, const Range& range);
CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, std::optional<double>& value,
                               const std::string& description, const Range& range);
// A comma-separated list of numbers, each within `range`.
CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, std::vector<double>& values,
                               const std::string& description, const Range& range);
// Whole numbers: the value must be written as one (no fraction, no exponent).
CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, int& value,
                               const std::string& description, const WholeRange& range);
CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, long long& value,
                               const std::string& description, const WholeRange& range);
CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, std::optional<long long>& value,
                               const std::string& description, const WholeRange& range);

// The range an option was registered with (for the documentation test); nullopt for an option
// without one.
std::optional<std::string> registered_range(const CLI::Option& option);

}  // namespace mark::cli
