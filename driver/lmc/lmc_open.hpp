#pragma once
// `--device` values naming an LMC board: "lmc" (the only board connected), "lmc:SERIAL" (the
// board whose GetSerialNo answer is SERIAL, as `marker devices` lists it) and
// "lmc-capture:FILE" (no board: the bytes for endpoint 0x02 go to FILE, see capture_link.hpp).
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "driver/lmc/lmc_device.hpp"

namespace mark::lmc {

struct LmcSpec {
  bool capture = false;
  std::string serial;  // usb: empty = the only board
  std::string file;    // capture
};

// Not an LMC spec: nullopt. A malformed one ("lmc:", "lmc:xyz", "lmc-capture:"): DeviceError
// naming it and the forms allowed.
std::optional<LmcSpec> parse_lmc_spec(std::string_view spec);

// Opens the board (or the capture file) and runs the init sequence.
std::unique_ptr<LmcDevice> open_lmc(const LmcSpec& spec, LmcOptions options);

}  // namespace mark::lmc
