#include "marker/cli/inject_option.hpp"

#include <charconv>

#include "base/error.hpp"

namespace mark::cli {
namespace {

// "outcome", "outcome:full", "allocate:locked:2".
StoreFaultPlan parse_store(const std::string& value, const std::string& spec) {
  const auto refuse = [&] {
    return InputError("--inject '" + value +
                      "': expected store@STEP[:FAULT[:ATTEMPTS]] with STEP allocate or outcome, FAULT locked, "
                      "full, io or stopped, ATTEMPTS 0 (every attempt) to 20");
  };
  StoreFaultPlan plan;
  std::string parts[3];
  std::size_t n = 0, start = 0;
  for (;;) {
    const std::size_t colon = spec.find(':', start);
    if (n == 3) throw refuse();
    parts[n++] = spec.substr(start, colon - start);
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  const auto step = parse_store_step(parts[0]);
  if (!step) throw refuse();
  plan.step = *step;
  if (n > 1) {
    const auto kind = parse_store_fault(parts[1]);
    if (!kind) throw refuse();
    plan.kind = *kind;
  }
  if (n > 2) {
    const std::string& a = parts[2];
    const auto [end, ec] = std::from_chars(a.data(), a.data() + a.size(), plan.attempts);
    if (a.empty() || ec != std::errc() || end != a.data() + a.size() || plan.attempts < 0 || plan.attempts > 20)
      throw refuse();
  }
  return plan;
}

}  // namespace

InjectArg parse_inject(const std::string& value) {
  const auto refuse = [&] {
    return InputError("--inject '" + value +
                      "': expected underrun@N, abort@N or fault@N with N a sample index from 0 "
                      "to 18446744073709551614, or store@STEP[:FAULT[:ATTEMPTS]]");
  };
  const std::size_t at = value.find('@');
  if (at == std::string::npos) throw refuse();
  const std::string kind = value.substr(0, at), number = value.substr(at + 1);
  InjectArg a;
  if (kind == "store") {
    a.store = parse_store(value, number);
    return a;
  }
  std::uint64_t n = 0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), n);
  if (number.empty() || ec != std::errc() || end != number.data() + number.size() || n == UINT64_MAX)
    throw refuse();
  if (kind == "underrun") a.drain = {Injection::Kind::underrun, n};
  else if (kind == "abort") a.drain = {Injection::Kind::abort, n};
  else if (kind == "fault") a.device_fault_at = n;
  else throw refuse();
  return a;
}

}  // namespace mark::cli
