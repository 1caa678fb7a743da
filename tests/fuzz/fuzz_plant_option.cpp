// libFuzzer target for `--plant KEY=VALUE,…` (marker/cli/plant_option.hpp): the input is either
// refused with an InputError or yields a plant the simulated scanner accepts (its constructor
// refuses a plant it cannot integrate) and that prints back (plant_text) to the same plant, so
// nothing the option lets through reaches the simulator out of range or is lost from mark_args.
#include <cstdint>
#include <string>

#include "base/error.hpp"
#include "driver/device_error.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "marker/cli/plant_option.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  mark::Plant plant;
  try {
    plant = mark::cli::parse_plant_option(text);
  } catch (const mark::InputError&) {
    return 0;
  }
  try {
    mark::SimScannerOptions o;
    o.plant = plant;
    o.record_lit_paths = false;
    mark::SimScanner sim(o);
  } catch (const mark::DeviceError&) {
    mark::fuzz::broken("--plant accepted a plant the simulator refuses");
  }
  const std::string printed = mark::cli::plant_text(plant);
  if (mark::cli::plant_text(mark::cli::parse_plant_option(printed)) != printed)
    mark::fuzz::broken("--plant does not print back to the same plant");
  return 0;
}
