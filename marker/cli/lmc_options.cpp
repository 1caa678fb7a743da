#include "marker/cli/lmc_options.hpp"

#include "base/error.hpp"
#include "driver/lmc/cor_file.hpp"
#include "marker/cli/option_ranges.hpp"

namespace mark::cli {
namespace {

const WholeRange kPortBitRange{0, 15};
// Below 0.5 µm a chord is shorter than the board's 16-bit field step on any lens.
const Range kChordToleranceRange{0.5, 1000, "µm"};

}  // namespace

void add_lmc_options(CLI::App& app, LmcArgs& a) {
  app.add_option("--cor", a.cor_file, "LMC: EzCad field-correction file (.cor, both formats) to upload");
  app.add_flag("--swap-xy", a.swap_xy, "LMC: the head's x and y galvos are swapped");
  app.add_flag("--flip-x", a.flip_x, "LMC: mirror x (the head's x galvo is wired reversed)");
  app.add_flag("--flip-y", a.flip_y, "LMC: mirror y");
  app.add_option("--source", a.source, "LMC: laser source")
      ->check(CLI::IsMember({"fiber", "mopa"}))
      ->capture_default_str();
  add_ranged_option(app, "--laser-bit", a.laser_bit, "LMC: output-port bit that enables the laser", kPortBitRange)
      ->capture_default_str();
  add_ranged_option(app, "--red-bit", a.red_bit, "LMC: output-port bit of the red pointer", kPortBitRange)
      ->capture_default_str();
  app.add_option("--polygon-delay-units", a.polygon_unit,
                 "LMC: PolygonDelay encoding: 10us (meerk40t since 2025) or us (galvoplotter)")
      ->check(CLI::IsMember({"10us", "us"}))
      ->capture_default_str();
  add_ranged_option(app, "--chord-tolerance", a.chord_tolerance_um,
                    "LMC: arcs become chords within this distance, µm", kChordToleranceRange)
      ->capture_default_str();
}

lmc::LmcOptions to_lmc_options(const LmcArgs& a, double field_mm) {
  if (!(field_mm > 0)) throw InputError("--field must be a positive size in mm");
  check_range("--chord-tolerance", a.chord_tolerance_um, kChordToleranceRange);
  if (a.laser_bit == a.red_bit) throw InputError("--laser-bit and --red-bit must differ");
  lmc::LmcOptions o;
  o.field_mm = field_mm;
  o.chord_tolerance_mm = a.chord_tolerance_um * 1e-3;
  o.axes = {a.swap_xy, a.flip_x, a.flip_y};
  o.source = a.source == "mopa" ? lmc::LaserSource::mopa : lmc::LaserSource::fiber;
  o.laser_port_bit = a.laser_bit;
  o.red_pointer_bit = a.red_bit;
  o.polygon_delay_unit = a.polygon_unit == "us" ? lmc::PolygonDelayUnit::signed_us
                                                : lmc::PolygonDelayUnit::ten_us;
  if (!a.cor_file.empty()) o.correction = lmc::read_cor_file(a.cor_file);
  return o;
}

}  // namespace mark::cli
