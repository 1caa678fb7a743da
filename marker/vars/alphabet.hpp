#pragma once
// The digits a serial number is written with: decimal, hex, base 36 (0-9A-Z), base 33 (base 36
// without I, O and Q, which VIN-style lists forbid because they read as 1 and 0), or a custom
// string of distinct characters (UTF-8). Padding of the leading positions follows RTC
// mark_serial: keep (leading zeros), suppress (left-justified, no leading zeros), blank
// (right-justified, leading zeros as spaces).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mark {

enum class Padding { keep, suppress, blank };

std::string_view to_string(Padding padding);
std::optional<Padding> parse_padding(std::string_view name);

class Alphabet {
 public:
  // Decimal.
  Alphabet();
  // "decimal", "hex", "base36", "base33"; nothing for another name.
  static std::optional<Alphabet> named(std::string_view name);
  // A custom alphabet: at least 2 distinct characters, none of them a space or a brace.
  // Throws InputError naming `what` otherwise.
  static Alphabet custom(std::string_view utf8_digits, std::string_view what);

  // The built-in name, or the digits themselves for a custom alphabet.
  const std::string& name() const { return name_; }
  bool is_custom() const { return custom_; }
  std::uint64_t base() const { return symbols_.size(); }

  // How many digits `value` (≥ 0) needs.
  int digits(std::int64_t value) const;
  // The largest value that fits in `width` digits (saturates at INT64_MAX).
  std::int64_t max_for_width(int width) const;
  // `value` (≥ 0) in this alphabet, padded to `width` digits (0: natural width). A value
  // needing more than `width` digits is written in full (callers refuse such limits up front).
  void format(std::int64_t value, int width, Padding padding, std::string& out) const;
  std::string format(std::int64_t value, int width = 0, Padding padding = Padding::keep) const {
    std::string s;
    format(value, width, padding, s);
    return s;
  }

 private:
  std::string name_;
  bool custom_ = false;
  std::vector<std::string> symbols_;  // one UTF-8 character per digit
};

}  // namespace mark
