#pragma once
// The hatch options of filled text (`--fill hatch`) and of a code's square modules:
//   --hatch-spacing MM[,MM…] --hatch-angle DEG[,DEG…]   one hatch set per value (cross-hatch:
//                                                        --hatch-angle 0,90); a single value
//                                                        applies to every set
//   --hatch-direction bidirectional|unidirectional  --hatch-order short|raster
//   --hatch-inset MM (the beam radius)
//   --contour-passes N --contour-placement before|after --contour-inset MM --contour-spacing MM
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "marker/fill/fill_options.hpp"
#include "marker/limits/fill_settings.hpp"

namespace mark::cli {

struct HatchArgs {
  // Defaults from the settings table (marker/limits/fill_settings.hpp).
  std::vector<double> spacing_mm;
  std::vector<double> angle_deg;
  std::string direction{kHatchDirection.value};
  std::string order{kHatchOrder.value};
  std::optional<double> inset_mm;
  int contour_passes = static_cast<int>(*kContourPasses.value);
  std::string contour_placement{kContourPlacement.value};
  std::optional<double> contour_inset_mm;
  std::optional<double> contour_spacing_mm;
};

void add_hatch_options(CLI::App& app, HatchArgs& args);

// The fill options; the inset (and the first contour's) default to `beam_radius_mm`. Throws
// InputError naming the option for a value out of range or lists of different lengths.
FillOptions to_fill_options(const HatchArgs& args, double beam_radius_mm = 0.02);

}  // namespace mark::cli
