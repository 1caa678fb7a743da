#pragma once
// Numbers in stroke-font files: decimal coordinates, integers and hexadecimal code points, read
// with std::from_chars (no locale, no allocation). Every coordinate a loader accepts is finite and
// at most kMaxFontValue in magnitude, so the geometry built from it cannot overflow.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace mark::loaders {

// Stroke fonts are drawn on grids of tens of units; anything this large is a corrupt file.
inline constexpr double kMaxFontValue = 1e6;

enum class NumberStatus { ok, malformed, not_finite, out_of_range };

// The decimal number at the start of `text` ("3", "-.41", "3.", "+2", "1e-3", also "nan" and
// "inf", which are then reported as not finite); `used` is how many characters it took. The
// status is `malformed` when `text` does not start with a number.
NumberStatus scan_number(std::string_view text, std::size_t& used, double& value);
// The whole of `token` as a decimal number. No surrounding spaces.
NumberStatus parse_number(std::string_view token, double& value);
// What is wrong, for messages: "is not a number", "is not finite", "is out of range".
const char* describe(NumberStatus status);

// parse_number, throwing FontFileError("<what> <token> is not a number") unless the status is ok.
double require_number(std::string_view token, const std::string& source, std::size_t line,
                      std::string_view what);

// A non-negative decimal integer, right-aligned in a fixed field (leading spaces allowed), as in
// the Hershey record columns. Empty optional if the field is not that.
std::optional<long> parse_field_integer(std::string_view field);

// A Unicode scalar value written as 1..max_digits hexadecimal digits (no prefix). Empty optional
// for anything else, for values past U+10FFFF and for surrogates.
std::optional<char32_t> parse_hex_code_point(std::string_view digits, std::size_t max_digits = 6);

}  // namespace mark::loaders
