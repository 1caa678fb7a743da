// libFuzzer target for the option-value parsers every numeric option goes through
// (marker/cli/option_values.hpp, option_ranges.hpp): one number, and "A,B,C" / "AxB" lists; and
// the machine's envelope (machine_values.hpp: --stock "W,H" / "X,Y,W,H", --travel "X,Y"). The
// input is either refused with an InputError or yields the promised count of numbers, and a
// number the range check lets through is finite and inside the range; a stock is a finite box
// inside the limits, a travel two finite numbers inside theirs.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "base/error.hpp"
#include "marker/cli/machine_values.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/limits/cnc_limits.hpp"
#include "marker/limits/layout_settings.hpp"

namespace {

[[noreturn]] void broken(const char* what, double v) {
  std::fprintf(stderr, "fuzz invariant broken: %s (%g)\n", what, v);
  std::abort();
}

void check(double v, const mark::Range& range) {
  try {
    mark::cli::check_range("--fuzz", v, range);
  } catch (const mark::InputError&) {
    if (range.contains(v)) broken("a value inside the range was refused", v);
    return;
  }
  if (!std::isfinite(v) || !range.contains(v)) broken("a value outside the range was accepted", v);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const mark::Range ranges[] = {{-360, 360, "degrees"}, {0, 1000, "mm", true}, {1, 100000, "rpm", false, true}};
  if (const auto v = mark::cli::parse_number(text))
    for (const auto& r : ranges) check(*v, r);
  // A whole number is written with digits and an optional sign only, and means what strtoll says.
  if (const auto w = mark::cli::parse_whole_number(text)) {
    const std::size_t first = text[0] == '+' || text[0] == '-' ? 1 : 0;
    if (text.find_first_not_of("0123456789", first) != std::string::npos)
      broken("a whole number with more than digits", static_cast<double>(*w));
    if (std::strtoll(text.c_str(), nullptr, 10) != *w) broken("a whole number read differently", static_cast<double>(*w));
  }
  for (const auto& [separators, count] : {std::pair<const char*, std::size_t>{",", 3}, {"xX", 2}}) {
    try {
      const auto values = mark::cli::parse_numbers("--fuzz", text, separators, count, "the format");
      if (values.size() != count) broken("wrong count of numbers", static_cast<double>(values.size()));
      for (double v : values)
        for (const auto& r : ranges) check(v, r);
    } catch (const mark::InputError&) {
    }
  }
  try {
    const mark::Box b = mark::cli::parse_stock(text);
    // The box's width is (x + w) - x: exact only to the rounding of its corners' magnitude (the
    // parser checked w itself), so a size counts as inside within a few ulps of that magnitude.
    const auto size_ok = [](double size, double lo, double hi) {
      const double ulps = 8 * std::numeric_limits<double>::epsilon() * (std::abs(lo) + std::abs(hi));
      return mark::kStockSizeRange.contains(size) || mark::kStockSizeRange.contains(size + ulps) ||
             mark::kStockSizeRange.contains(size - ulps);
    };
    const double w = b.width(), h = b.height();
    if (!size_ok(w, b.min.x(), b.max.x()) || !size_ok(h, b.min.y(), b.max.y()))
      broken("a stock size outside its range", w);
    if (!mark::kPositionBounds.range().contains(b.min.x()) || !mark::kPositionBounds.range().contains(b.min.y()))
      broken("a stock corner outside its range", b.min.x());
  } catch (const mark::InputError&) {
  }
  try {
    const auto [x, y] = mark::cli::parse_travel(text);
    if (!mark::kTravelRange.contains(x) || !mark::kTravelRange.contains(y)) broken("a travel outside its range", x);
  } catch (const mark::InputError&) {
  }
  return 0;
}
