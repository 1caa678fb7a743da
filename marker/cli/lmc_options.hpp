#pragma once
// The options every command that drives an LMC board shares: the correction file, how the head
// is wired (--swap-xy, --flip-x, --flip-y), the output-port bits, the polygon delay's units and
// the chord tolerance. The lens field is the layout's --field; the laser source is the pen's
// (--source).
#include <CLI/CLI.hpp>
#include <string>

#include "driver/lmc/lmc_device.hpp"
#include "marker/limits/device_settings.hpp"

namespace mark::cli {

struct LmcArgs {
  // Defaults from the settings table (marker/limits/device_settings.hpp).
  std::string cor_file;
  bool swap_xy = kSwapXy.on, flip_x = kFlipX.on, flip_y = kFlipY.on;
  int laser_bit = static_cast<int>(*kLaserBit.value);
  int red_bit = static_cast<int>(*kRedBit.value);
  std::string polygon_unit{kPolygonDelayUnits.value};
  bool word_ticks = kWordTicks.on;
  double chord_tolerance_um = *kChordTolerance.value;
};

void add_lmc_options(CLI::App& app, LmcArgs& args);

// The board options for a lens field of field_mm. Reads the correction file; throws
// InputError (or the reader's error) naming what is wrong.
lmc::LmcOptions to_lmc_options(const LmcArgs& args, double field_mm);

}  // namespace mark::cli
