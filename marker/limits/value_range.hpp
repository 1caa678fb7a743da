#pragma once
// The allowed range of a number a user gives — on the command line or in a job file — and its
// wording in messages and help. A setting's range is declared once, in its settings table
// (setting.hpp, *_settings.hpp), so `--height` and a job file's `height_mm` accept the same values
// and say so in the same words; the values inside one option (--camera's keys, --stock's sizes)
// keep their ranges in *_limits.hpp beside them.
#include <cstdint>
#include <string>
#include <string_view>

namespace mark {

struct Range {
  double min = 0;
  double max = 0;
  std::string unit;           // "mm", "degrees", "mm/s", … (empty for a plain factor)
  bool above_min = false;     // min itself is excluded: min < v
  bool zero_means = false;    // 0 is also accepted (a documented "off" or "automatic")

  bool contains(double v) const;  // false for NaN and infinities
  // "-360 to 360 degrees", "above 0, up to 50 mm", "0, or 1 to 100000 rpm".
  std::string text() const;
};

// Whole numbers (counts, counter values), exact over the whole 64-bit range.
struct WholeRange {
  std::int64_t min = 0;
  std::int64_t max = 0;
  bool contains(std::int64_t v) const { return v >= min && v <= max; }
  std::string text() const;  // "1 to 100"
};

Range length_range(double min_mm, double max_mm);    // min ≤ v ≤ max, mm
Range positive_up_to(double max, std::string unit);  // 0 < v ≤ max

// Throws InputError "NAME: VALUE is outside the range RANGE" when v is outside the range or not a
// finite number. `typed` is the value as the user wrote it (empty: v formatted).
void check_range(std::string_view name, double v, const Range& range, std::string_view typed = {});

// Numbers in messages: as short as exact enough ("1e+20", "0.025", "58.3333").
std::string format_number(double v);

}  // namespace mark
