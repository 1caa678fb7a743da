#pragma once
// The options every command that drives an LMC board shares: the correction file, how the head
// is wired (--swap-xy, --flip-x, --flip-y), the output-port bits, the polygon delay's units and
// the chord tolerance. The lens field is the layout's --field; the laser source is the pen's
// (--source).
#include <CLI/CLI.hpp>
#include <string>

#include "driver/lmc/lmc_device.hpp"

namespace mark::cli {

struct LmcArgs {
  std::string cor_file;
  bool swap_xy = lmc::kEzCadAxes.swap_xy, flip_x = lmc::kEzCadAxes.flip_x, flip_y = lmc::kEzCadAxes.flip_y;
  int laser_bit = 0;
  int red_bit = 8;
  std::string polygon_unit = "us";
  double chord_tolerance_um = 5;
};

void add_lmc_options(CLI::App& app, LmcArgs& args);

// The board options for a lens field of field_mm. Reads the correction file; throws
// InputError (or the reader's error) naming what is wrong.
lmc::LmcOptions to_lmc_options(const LmcArgs& args, double field_mm);

}  // namespace mark::cli
