#pragma once
// Device names for an LMC board, as `--device` and a job file's "device" take them: "lmc" (the
// only board connected), "lmc:SERIAL" (the board whose GetSerialNo answer is SERIAL, as
// `marker devices` lists it), "lmc-capture:FILE" (no board: the bytes for endpoint 0x02 go
// to FILE, see capture_link.hpp) and "lmc-emulated[:VARIANT]" (the emulated board, in one of its
// behaviour variants: emulated_link.hpp). No I/O here, so a job file can be checked without
// libusb.
#include <optional>
#include <string>
#include <string_view>

namespace mark::lmc {

struct LmcSpec {
  bool capture = false;
  bool emulated = false;
  std::string serial;  // usb: empty = the only board
  std::string file;    // capture
  std::string variant = "reference";  // emulated: the board's behaviour variant
};

// Not an LMC spec: nullopt. A malformed one ("lmc:", "lmc:xyz", "lmc-capture:"): DeviceError
// naming it (after `what`, the option it came from, if not empty) and the forms allowed.
std::optional<LmcSpec> parse_lmc_spec(std::string_view spec, std::string_view what = "--device");

}  // namespace mark::lmc
