// Fuzz target for `marker serve --trigger` and `--signal` (marker/station/board_io.hpp): any text
// either parses — a trigger bit 0–15; signals with bits 0–15, no bit twice, and a mask that is
// exactly their bits — or throws InputError whose one-line message names the option. Anything
// else is a bug.
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>

#include "base/error.hpp"
#include "fuzz_check.hpp"
#include "marker/station/board_io.hpp"

using mark::fuzz::broken;

namespace {

void check_message(const mark::InputError& e, std::string_view option) {
  const std::string m = e.what();
  if (m.rfind(std::string(option) + ": ", 0) != 0) broken("an error that does not name its option");
  if (m.find('\n') != std::string::npos || m.find('\r') != std::string::npos) broken("a message with a line break");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const int b = mark::parse_board_trigger(text, "--trigger");
    if (b < 0 || b > 15) broken("a trigger bit outside 0-15 accepted");
  } catch (const mark::InputError& e) {
    check_message(e, "--trigger");
  }
  try {
    const mark::BoardSignals s = mark::parse_board_signals(text, "--signal");
    int n = 0;
    for (const auto* b : {&s.ready, &s.busy, &s.done, &s.error}) {
      if (!*b) continue;
      ++n;
      if (**b < 0 || **b > 15) broken("a signal bit outside 0-15 accepted");
    }
    if (n == 0) broken("signals accepted with none given");
    if (std::popcount(static_cast<unsigned>(s.mask())) != n) broken("one bit given to two signals");
  } catch (const mark::InputError& e) {
    check_message(e, "--signal");
  }
  return 0;
}
