#pragma once
// Options whose value is a list of KEY=VALUE numbers (`--camera pixel_um=20,defocus_um=40`,
// `--plant tau_scale=1.1,dead_us=10`): one parser, so every such option refuses a bad item in the
// same words — the option, the key, the value as typed and the key's range.
#include <cstddef>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "marker/limits/value_range.hpp"

namespace mark::cli {

struct NumberKey {
  std::string_view name;
  const Range* range;
  bool whole = false;  // a count or a seed: no fraction
};

// (index into keys, value) of every item of `text` in order; "" gives none. Throws InputError
// "OPTION 'ITEM': expected KEY=VALUE, e.g. EXAMPLE", "OPTION: unknown key 'K' (keys: …)",
// "OPTION K: 'V' is not a number (range: …)", "OPTION K: V is outside the range …" or
// "OPTION K: 'V' is not a whole number".
std::vector<std::pair<std::size_t, double>> parse_number_keys(std::string_view option, std::string_view text,
                                                              std::span<const NumberKey> keys,
                                                              std::string_view example);

}  // namespace mark::cli
