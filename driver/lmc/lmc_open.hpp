#pragma once
// Opening the board a device name (lmc_spec.hpp) names.
#include <memory>

#include "driver/lmc/lmc_device.hpp"
#include "driver/lmc/lmc_spec.hpp"

namespace mark::lmc {

// Opens the board (or the capture file) and runs the init sequence.
std::unique_ptr<LmcDevice> open_lmc(const LmcSpec& spec, LmcOptions options);

}  // namespace mark::lmc
