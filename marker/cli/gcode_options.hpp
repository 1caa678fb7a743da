#pragma once
// The options of `marker gcode` and the checks between them: the cut (mode, tool, depths,
// feeds), V-carving, the G-code frame (dialect, units, header/footer), protrusion, tool
// measurement, the machine's envelope (stock, travel) and the outputs.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "marker/cli/layout_options.hpp"
#include "marker/cnc/cut_settings.hpp"
#include "marker/cnc/gcode_options.hpp"
#include "marker/cnc/machine_envelope.hpp"
#include "marker/cnc/protrusion.hpp"
#include "marker/cnc/vcarve.hpp"

namespace mark::cli {

struct GcodeArgs {
  std::string text;
  LayoutArgs layout;
  std::string mode = "depression";
  CutSettings cut;
  ProtrusionSettings protrusion;
  GcodeOptions gcode;
  std::string dialect = "linuxcnc";
  std::string units = "mm";
  bool m2 = false;
  std::string tool_image;
  double pixel_size_um = 0;
  // V-carving: unset means not given (refused outside --mode v-carve).
  std::optional<double> bit_angle_deg, max_depth_mm, flat_bottom_mm, carve_tolerance_mm;
  std::string cleanup_output;
  std::string fill_rule;
  // The machine: "W,H" or "X,Y,W,H" (mm), "X,Y" (mm).
  std::string stock;
  std::string travel;
  std::string output;
  std::string preview;
  bool json = false;
  bool quiet = false;

  bool protrusion_mode() const { return mode == "protrusion"; }
  bool vcarve_mode() const { return mode == "v-carve"; }
};

void add_gcode_options(CLI::App& app, GcodeArgs& args);

// The checks that need more than one option (single values were checked while parsing), and
// the dialect and units parsed into the writer's options. Throws InputError naming the options.
void check_gcode_args(GcodeArgs& args);

// The V-carve settings from the arguments (defaults where not given).
VCarveSettings vcarve_settings(const GcodeArgs& args);

// --stock and --travel; without them, no stock and the largest table's travel.
MachineEnvelope machine_envelope(const GcodeArgs& args);

}  // namespace mark::cli
