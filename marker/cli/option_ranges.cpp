#include "marker/cli/option_ranges.hpp"

#include <cmath>
#include <type_traits>

#include "base/error.hpp"
#include "marker/cli/option_values.hpp"

namespace mark::cli {
namespace {

constexpr std::string_view kRangeTag = " (range: ";

CLI::Validator range_validator(const Range& range) {
  CLI::Validator v(
      [range](std::string& value) -> std::string {
        const std::optional<double> n = parse_number(value);
        if (!n) return "'" + value + "' is not a number (range: " + range.text() + ")";
        if (!std::isfinite(*n) || !range.contains(*n))
          return value + " is outside the range " + range.text();
        return {};
      },
      "", "range");
  return v;
}

CLI::Validator whole_validator(const WholeRange& range) {
  return CLI::Validator(
      [range](std::string& value) -> std::string {
        const std::optional<long long> n = parse_whole_number(value);
        if (!n) return "'" + value + "' is not a whole number (range: " + range.text() + ")";
        if (!range.contains(*n)) return value + " is outside the range " + range.text();
        return {};
      },
      "", "range");
}

template <class T, class R>
CLI::Option* add_ranged(CLI::App& app, const std::string& name, T& value,
                        const std::string& description, const R& range) {
  CLI::Option* o = app.add_option(name, value, description + std::string(kRangeTag) + range.text() + ")");
  if constexpr (std::is_same_v<R, Range>)
    o->check(range_validator(range));
  else
    o->check(whole_validator(range));
  return o;
}

}  // namespace

CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, double& value,
                               const std::string& description, const Range& range) {
  return add_ranged(app, name, value, description, range);
}

CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, std::optional<double>& value,
                               const std::string& description, const Range& range) {
  return add_ranged(app, name, value, description, range);
}

CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, std::vector<double>& values,
                               const std::string& description, const Range& range) {
  return add_ranged(app, name, values, description, range)->delimiter(',');
}

CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, int& value,
                               const std::string& description, const WholeRange& range) {
  return add_ranged(app, name, value, description, range);
}

CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, long long& value,
                               const std::string& description, const WholeRange& range) {
  return add_ranged(app, name, value, description, range);
}

CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, std::optional<long long>& value,
                               const std::string& description, const WholeRange& range) {
  return add_ranged(app, name, value, description, range);
}

std::optional<std::string> registered_range(const CLI::Option& option) {
  const std::string& d = option.get_description();
  const std::size_t at = d.rfind(kRangeTag);
  if (at == std::string::npos || d.back() != ')') return std::nullopt;
  const std::size_t from = at + kRangeTag.size();
  return d.substr(from, d.size() - 1 - from);
}

}  // namespace mark::cli
