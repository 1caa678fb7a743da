#include "fonts/loaders/numbers.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>

#include "fonts/error.hpp"
#include "fonts/loaders/text_lines.hpp"

namespace mark::loaders {
namespace {

// Font files are mostly short plain decimals ("0.428571", "-3", ".5"). Those with at most 15
// significant digits convert exactly: the digits as an integer (< 2^53) divided by an exact power
// of ten is one correctly rounded operation (Clinger's fast path), so the result equals
// from_chars'. Returns the characters used, or 0 when the number needs from_chars (exponent,
// long mantissa) or there is none.
std::size_t scan_plain_decimal(std::string_view text, double& value) {
  static constexpr double kPow10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  std::size_t i = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (negative) ++i;
  std::uint64_t mantissa = 0;
  int digits = 0, fraction_digits = 0;
  bool point = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c >= '0' && c <= '9') {
      if (++digits > 15) return 0;
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
      fraction_digits += point;
    } else if (c == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  if (digits == 0) return 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) return 0;
  const double magnitude = static_cast<double>(mantissa) / kPow10[fraction_digits];
  value = negative ? -magnitude : magnitude;
  return i;
}

}  // namespace

NumberStatus scan_number(std::string_view text, std::size_t& used, double& value) {
  used = 0;
  // from_chars takes no '+' sign; a font file may write one.
  std::size_t sign = 0;
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') sign = 1;
  const std::string_view body = text.substr(sign);
  std::size_t n = scan_plain_decimal(body, value);
  if (n == 0) {
    const char* end = body.data() + body.size();
    const auto [ptr, ec] = std::from_chars(body.data(), end, value, std::chars_format::general);
    n = static_cast<std::size_t>(ptr - body.data());
    if (n == 0) return NumberStatus::malformed;
    used = sign + n;
    if (ec == std::errc::result_out_of_range) return NumberStatus::out_of_range;
    if (ec != std::errc()) return NumberStatus::malformed;
  }
  used = sign + n;
  if (!std::isfinite(value)) return NumberStatus::not_finite;
  if (std::abs(value) > kMaxFontValue) return NumberStatus::out_of_range;
  return NumberStatus::ok;
}

NumberStatus parse_number(std::string_view token, double& value) {
  std::size_t used = 0;
  const NumberStatus status = scan_number(token, used, value);
  if (used != token.size()) return NumberStatus::malformed;
  return status;
}

const char* describe(NumberStatus status) {
  switch (status) {
    case NumberStatus::ok:
      return "is fine";
    case NumberStatus::malformed:
      return "is not a number";
    case NumberStatus::not_finite:
      return "is not finite";
    case NumberStatus::out_of_range:
      return "is out of range (|value| > 1e6)";
  }
  return "is not a number";
}

double require_number(std::string_view token, const std::string& source, std::size_t line,
                      std::string_view what) {
  double value = 0;
  const NumberStatus status = parse_number(token, value);
  if (status != NumberStatus::ok)
    throw FontFileError(source, line,
                        std::string(what) + " " + quote(token) + " " + describe(status));
  return value;
}

std::optional<long> parse_field_integer(std::string_view field) {
  while (!field.empty() && field.front() == ' ') field.remove_prefix(1);
  if (field.empty()) return std::nullopt;
  long value = 0;
  const char* end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, value, 10);
  if (ec != std::errc() || ptr != end || value < 0) return std::nullopt;
  return value;
}

std::optional<char32_t> parse_hex_code_point(std::string_view digits, std::size_t max_digits) {
  if (digits.empty() || digits.size() > max_digits) return std::nullopt;
  unsigned long value = 0;
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value, 16);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  if (value > 0x10FFFF || (value >= 0xD800 && value <= 0xDFFF)) return std::nullopt;
  return static_cast<char32_t>(value);
}

}  // namespace mark::loaders
