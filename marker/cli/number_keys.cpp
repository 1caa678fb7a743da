#include "marker/cli/number_keys.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.hpp"
#include "marker/cli/option_values.hpp"

namespace mark::cli {

std::vector<std::pair<std::size_t, double>> parse_number_keys(std::string_view option, std::string_view text,
                                                              std::span<const NumberKey> keys,
                                                              std::string_view example) {
  const std::string opt(option);
  std::vector<std::pair<std::size_t, double>> out;
  std::size_t at = 0;
  while (at <= text.size() && !text.empty()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item(text.substr(at, comma - at));
    at = comma + 1;
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos)
      throw InputError(opt + " '" + item + "': expected KEY=VALUE, e.g. " + std::string(example));
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    const auto k = std::find_if(keys.begin(), keys.end(), [&](const NumberKey& c) { return key == c.name; });
    if (k == keys.end()) {
      std::string names;
      for (const NumberKey& c : keys) names += (names.empty() ? "" : ", ") + std::string(c.name);
      throw InputError(opt + ": unknown key '" + key + "' (keys: " + names + ")");
    }
    const std::optional<double> v = parse_number(value);
    if (!v) throw InputError(opt + " " + key + ": '" + value + "' is not a number (range: " + k->range->text() + ")");
    check_range(opt + " " + key, *v, *k->range, value);
    if (k->whole && *v != std::floor(*v)) throw InputError(opt + " " + key + ": '" + value + "' is not a whole number");
    out.emplace_back(static_cast<std::size_t>(k - keys.begin()), *v);
  }
  return out;
}

}  // namespace mark::cli
