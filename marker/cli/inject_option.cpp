#include "marker/cli/inject_option.hpp"

#include <charconv>

#include "base/error.hpp"

namespace mark::cli {

InjectArg parse_inject(const std::string& value) {
  const auto refuse = [&] {
    return InputError("--inject '" + value +
                      "': expected underrun@N, abort@N or fault@N with N a sample index from 0 "
                      "to 18446744073709551614");
  };
  const std::size_t at = value.find('@');
  if (at == std::string::npos) throw refuse();
  const std::string kind = value.substr(0, at), number = value.substr(at + 1);
  std::uint64_t n = 0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), n);
  if (number.empty() || ec != std::errc() || end != number.data() + number.size() || n == UINT64_MAX)
    throw refuse();
  InjectArg a;
  if (kind == "underrun") a.drain = {Injection::Kind::underrun, n};
  else if (kind == "abort") a.drain = {Injection::Kind::abort, n};
  else if (kind == "fault") a.device_fault_at = n;
  else throw refuse();
  return a;
}

}  // namespace mark::cli
