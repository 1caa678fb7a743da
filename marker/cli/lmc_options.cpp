#include "marker/cli/lmc_options.hpp"

#include "base/error.hpp"
#include "driver/lmc/cor_file.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/limits/device_settings.hpp"

namespace mark::cli {

// The table's defaults are EzCad's axes, as the driver names them.
static_assert(kSwapXy.on == lmc::kEzCadAxes.swap_xy && kFlipX.on == lmc::kEzCadAxes.flip_x &&
              kFlipY.on == lmc::kEzCadAxes.flip_y);

void add_lmc_options(CLI::App& app, LmcArgs& a) {
  add_setting(app, kCorrectionFile, a.cor_file);
  add_setting(app, kSwapXy, a.swap_xy);
  add_setting(app, kFlipX, a.flip_x);
  add_setting(app, kFlipY, a.flip_y);
  add_setting(app, kLaserBit, a.laser_bit);
  add_setting(app, kRedBit, a.red_bit);
  add_setting(app, kPolygonDelayUnits, a.polygon_unit);
  add_setting(app, kWordTicks, a.word_ticks);
  add_setting(app, kChordTolerance, a.chord_tolerance_um);
}

lmc::LmcOptions to_lmc_options(const LmcArgs& a, double field_mm) {
  if (!(field_mm > 0)) throw InputError("--field must be a positive size in mm");
  check_setting(kChordTolerance, a.chord_tolerance_um);
  if (a.laser_bit == a.red_bit) throw InputError("--laser-bit and --red-bit must differ");
  lmc::LmcOptions o;
  o.field_mm = field_mm;
  o.chord_tolerance_mm = a.chord_tolerance_um * 1e-3;
  o.axes = {a.swap_xy, a.flip_x, a.flip_y};
  o.laser_port_bit = a.laser_bit;
  o.red_pointer_bit = a.red_bit;
  o.polygon_delay_unit = a.polygon_unit == "us" ? lmc::PolygonDelayUnit::signed_us
                                                : lmc::PolygonDelayUnit::ten_us;
  o.word_ticks = a.word_ticks;
  if (!a.cor_file.empty()) o.correction = lmc::read_cor_file(a.cor_file);
  return o;
}

}  // namespace mark::cli
