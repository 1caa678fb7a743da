#include "marker/cli/option_ranges.hpp"

#include <cmath>
#include <cstdio>

#include "fonts/error.hpp"
#include "marker/cli/option_values.hpp"

namespace mark::cli {
namespace {

constexpr std::string_view kRangeTag = " (range: ";

std::string with_unit(const std::string& s, const std::string& unit) {
  return unit.empty() ? s : s + " " + unit;
}

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

template <class T>
CLI::Option* add_ranged(CLI::App& app, const std::string& name, T& value,
                        const std::string& description, const Range& range) {
  CLI::Option* o = app.add_option(name, value, description + std::string(kRangeTag) + range.text() + ")");
  o->check(range_validator(range));
  return o;
}

}  // namespace

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (zero_means && v == 0) return true;
  return (above_min ? v > min : v >= min) && v <= max;
}

std::string Range::text() const {
  const std::string span = above_min ? "above " + format_number(min) + ", up to " + format_number(max)
                                     : format_number(min) + " to " + format_number(max);
  return (zero_means ? "0, or " : "") + with_unit(span, unit);
}

Range length_range(double min_mm, double max_mm) { return Range{min_mm, max_mm, "mm"}; }

Range positive_up_to(double max, std::string unit) { return Range{0, max, std::move(unit), true}; }

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void check_range(std::string_view option, double v, const Range& range, std::string_view typed) {
  if (range.contains(v)) return;
  const std::string shown = typed.empty() ? format_number(v) : std::string(typed);
  throw InputError(std::string(option) + ": " + shown + " is outside the range " + range.text());
}

CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, double& value,
                               const std::string& description, const Range& range) {
  return add_ranged(app, name, value, description, range);
}

CLI::Option* add_ranged_option(CLI::App& app, const std::string& name, std::optional<double>& value,
                               const std::string& description, const Range& range) {
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
