#pragma once
// `--plant KEY=VALUE,…`: the simulated head as it is, apart from the planner's model of it
// (driver/sim/plant.hpp; keys and ranges in marker/limits/plant_limits.hpp; docs/speed.md).
#include <string>

#include "driver/sim/plant.hpp"

namespace mark::cli {

// "" is the model itself. Throws InputError naming the key, the value and its range.
Plant parse_plant_option(const std::string& text);
// The KEY=VALUE text that parses back to `plant` (only the keys that differ from the model's;
// "" for the model), so a printed command line reproduces the plant.
std::string plant_text(const Plant& plant);
// One line per key: "tau_scale (0.5 to 2, default 1): …", for help texts.
std::string plant_keys_help();

}  // namespace mark::cli
