// libFuzzer target for `--camera KEY=VALUE,…` (marker/cli/code_options.hpp): the input is either
// refused with an InputError or yields camera settings that pass the camera's own range check
// (check_camera_settings), so nothing the option lets through can reach the camera model out of
// range.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "base/error.hpp"
#include "driver/sim/camera_model.hpp"
#include "marker/cli/code_options.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  mark::CameraSettings settings;
  try {
    settings = mark::cli::parse_camera_option(text);
  } catch (const mark::InputError&) {
    return 0;
  }
  try {
    mark::check_camera_settings(settings);
  } catch (const std::invalid_argument&) {
    mark::fuzz::broken("--camera accepted settings the camera refuses");
  }
  return 0;
}
