#include "marker/limits/value_range.hpp"

#include <cmath>
#include <cstdio>

#include "base/error.hpp"

namespace mark {

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (zero_means && v == 0) return true;
  return (above_min ? v > min : v >= min) && v <= max;
}

std::string Range::text() const {
  std::string span = above_min ? "above " + format_number(min) + ", up to " + format_number(max)
                               : format_number(min) + " to " + format_number(max);
  if (!unit.empty()) span += " " + unit;
  return (zero_means ? "0, or " : "") + span;
}

std::string WholeRange::text() const { return std::to_string(min) + " to " + std::to_string(max); }

Range length_range(double min_mm, double max_mm) { return Range{min_mm, max_mm, "mm"}; }

Range positive_up_to(double max, std::string unit) { return Range{0, max, std::move(unit), true}; }

void check_range(std::string_view name, double v, const Range& range, std::string_view typed) {
  if (range.contains(v)) return;
  const std::string shown = typed.empty() ? format_number(v) : std::string(typed);
  throw InputError(std::string(name) + ": " + shown + " is outside the range " + range.text());
}

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace mark
