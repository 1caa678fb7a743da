#pragma once
// Option values that hold numbers: one number ("1e-3"), or a fixed count of numbers separated by
// one character ("CX,CY,R" for --circle, "WxH" for --window). One parser for all of them, so every
// option reads numbers the same way (C's strtod over the whole text; nothing may trail).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mark::cli {

// The whole text as one number (which may be infinite or NaN: range checks refuse those); nothing
// when it is empty, is not a number or has anything after the number.
std::optional<double> parse_number(std::string_view text);

// The whole text as a whole number (digits with an optional sign, within 64 bits); nothing for
// anything else, a fraction or an exponent included.
std::optional<long long> parse_whole_number(std::string_view text);

// The shortest text that parses back to exactly v ("0.1", "1.02", "4294967295"), for printed
// command lines that must reproduce a run.
std::string exact_number(double v);

// Exactly `count` numbers separated by any one of `separators`. Throws InputError
// "OPTION 'TEXT': expected FORMAT" for the wrong count and "OPTION 'TEXT': 'PART' is not a number".
std::vector<double> parse_numbers(std::string_view option, std::string_view text, std::string_view separators,
                                  std::size_t count, std::string_view format);

}  // namespace mark::cli
