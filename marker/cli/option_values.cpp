#include "marker/cli/option_values.hpp"

#include <charconv>
#include <cstdlib>

#include "base/error.hpp"

namespace mark::cli {

std::optional<double> parse_number(std::string_view text) {
  if (text.empty()) return std::nullopt;
  const std::string s(text);  // strtod needs the terminating zero
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) return std::nullopt;
  return v;
}

std::string exact_number(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::optional<long long> parse_whole_number(std::string_view text) {
  long long v = 0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  // One sign at most: from_chars reads a '-' itself, so "+-13" must stop here.
  if (begin == end || (begin != text.data() && *begin == '-')) return std::nullopt;
  const auto [stop, error] = std::from_chars(begin, end, v);
  if (error != std::errc() || stop != end) return std::nullopt;
  return v;
}

std::vector<double> parse_numbers(std::string_view option, std::string_view text, std::string_view separators,
                                  std::size_t count, std::string_view format) {
  const std::string who = std::string(option) + " '" + std::string(text) + "'";
  std::vector<double> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find_first_of(separators, start);
    const std::string_view part = text.substr(start, end == std::string_view::npos ? text.npos : end - start);
    if (out.size() == count) throw InputError(who + ": expected " + std::string(format));
    const std::optional<double> v = parse_number(part);
    if (!v) {
      if (part.empty()) throw InputError(who + ": expected " + std::string(format));
      throw InputError(who + ": '" + std::string(part) + "' is not a number");
    }
    out.push_back(*v);
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  if (out.size() != count) throw InputError(who + ": expected " + std::string(format));
  return out;
}

}  // namespace mark::cli
