#pragma once
// `marker serve --trigger lmc-input:BIT --signal ready=B,…`: the station's BoardIo
// (marker/station/board_io.hpp) on the LMC board the station marks on — ReadPort for the
// trigger, the device's signal bits and WritePort for the outputs. Here, not in the station,
// because only the command line knows the device is an LMC board (marker/station/ includes no
// driver/lmc/).
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "driver/device.hpp"
#include "marker/station/board_io.hpp"

namespace mark::cli {

struct BoardIoArgs {
  std::string trigger;  // empty: none
  std::string signal;   // empty: none
  double debounce_ms = 0, min_pulse_ms = 0;  // the settings' defaults (add_setting)
};

// The options, parsed before anything opens; nothing when neither --trigger nor --signal is
// given. InputError (one line: the option, what is wrong, what is allowed) for a bad value.
std::optional<BoardIoOptions> parse_board_io(const BoardIoArgs& args);

// The board I/O on `device`. InputError for a device that is no LMC board, or an output bit that
// is the board's laser or red-pointer bit.
std::unique_ptr<BoardIo> open_board_io(Station& station, Device& device, const BoardIoOptions& options,
                                       std::function<void(const std::string&)> log);

}  // namespace mark::cli
