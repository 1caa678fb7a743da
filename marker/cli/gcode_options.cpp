#include "marker/cli/gcode_options.hpp"

#include <tuple>

#include "base/error.hpp"
#include "marker/cli/machine_values.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/tool_measure_report.hpp"
#include "marker/limits/cnc_settings.hpp"
#include "marker/limits/layout_settings.hpp"

namespace mark::cli {
namespace {

// Pocket loops closer than 5 % of the tool diameter only multiply the cutting time.
constexpr double kMinStepoverShare = 0.05;

}  // namespace

void add_gcode_options(CLI::App& sub, GcodeArgs& a) {
  sub.add_option("text", a.text, "text to engrave (UTF-8; \\n starts a new line)")->required();
  add_layout_options(sub, a.layout, kFont, /*galvo_field=*/false);
  add_spacing_options(sub, a.layout);
  add_setting(sub, kCncMode, a.mode);
  add_setting(sub, kToolDiameter, a.cut.tool_diameter_mm);
  add_setting(sub, kDepth, a.cut.depth_mm);
  add_setting(sub, kDepthPerPass, a.cut.depth_per_pass_mm);
  add_setting(sub, kSafeZ, a.cut.safe_z_mm);
  add_setting(sub, kFeed, a.cut.feed_mm_min);
  add_setting(sub, kPlungeFeed, a.cut.plunge_feed_mm_min);
  add_setting(sub, kSpindle, a.gcode.spindle_rpm);
  add_setting(sub, kDialect, a.dialect);
  add_setting(sub, kUnits, a.units);
  add_setting(sub, kHeader, a.gcode.header)->allow_extra_args(false);
  add_setting(sub, kFooter, a.gcode.footer)->allow_extra_args(false);
  add_setting(sub, kTitle, a.gcode.title);
  add_setting(sub, kM2, a.m2);
  add_setting(sub, kArcTolerance, a.cut.arcs.tolerance_mm);
  add_setting(sub, kEllipseChords, a.cut.arcs.ellipse_chords);
  add_setting(sub, kStrokeWidth, a.protrusion.stroke_width_mm);
  add_setting(sub, kMargin, a.protrusion.margin_mm);
  add_setting(sub, kStepover, a.protrusion.stepover_mm);
  add_setting(sub, kCutterComp, a.protrusion.cutter_comp);
  sub.add_option("--tool-image", a.tool_image,
                 "shadow image of the tool (PNG or PGM): its measured diameter replaces --tool-diameter in the offsets");
  add_setting(sub, kPixelSize, a.pixel_size_um);
  // V-carving: unset means not given, so another mode can refuse them (check_gcode_args).
  add_setting(sub, kBitAngle, a.bit_angle_deg);
  add_setting(sub, kMaxDepth, a.max_depth_mm);
  add_setting(sub, kFlatBottom, a.flat_bottom_mm);
  sub.add_option("--cleanup-output", a.cleanup_output, "v-carve: G-code file for the flat-bottom end mill");
  add_setting(sub, kCarveTolerance, a.carve_tolerance_mm);
  add_setting(sub, kCarveFillRule, a.fill_rule);
  add_setting(sub, kStock, a.stock);
  add_setting(sub, kTravel, a.travel);
  sub.add_option("-o,--output", a.output, "G-code file to write")->required();
  sub.add_option("--preview", a.preview, "draw the toolpath to FILE.svg or FILE.png");
  sub.add_flag("--json", a.json, "print the result as one JSON object (docs/json.md)");
  sub.add_flag("--quiet", a.quiet, "no progress lines on stderr");
}

void check_gcode_args(GcodeArgs& a) {
  a.gcode.dialect = parse_dialect(a.dialect);
  a.gcode.units = parse_units(a.units);
  a.gcode.end_with_m30 = !a.m2;
  const bool protrusion = a.protrusion_mode(), vcarve = a.vcarve_mode();
  if (a.protrusion.cutter_comp && !protrusion)
    throw InputError("--cutter-comp: only protrusion walls can be compensated by the control");
  if (a.protrusion.cutter_comp && a.gcode.dialect == Dialect::plain)
    throw InputError("--cutter-comp needs --dialect linuxcnc or fanuc: grbl has no G41/G42");
  if (!vcarve) {
    const std::pair<bool, const char*> vcarve_only[] = {{a.bit_angle_deg.has_value(), "--bit-angle"},
                                                        {a.max_depth_mm.has_value(), "--max-depth"},
                                                        {a.flat_bottom_mm.has_value(), "--flat-bottom"},
                                                        {a.carve_tolerance_mm.has_value(), "--carve-tolerance"},
                                                        {!a.cleanup_output.empty(), "--cleanup-output"},
                                                        {!a.fill_rule.empty(), "--fill-rule"}};
    for (const auto& [given, name] : vcarve_only)
      if (given) throw InputError(std::string(name) + " applies to --mode v-carve only (the mode is " + a.mode + ")");
  } else {
    if (a.flat_bottom_mm && a.cleanup_output.empty())
      throw InputError("--flat-bottom needs --cleanup-output FILE.ngc: the end mill runs its own program after a tool change");
    if (!a.cleanup_output.empty() && !a.flat_bottom_mm)
      throw InputError("--cleanup-output needs --flat-bottom MM, the diameter of the clean-up end mill");
  }
  const std::optional<double> stepped = vcarve ? a.flat_bottom_mm : std::optional<double>(a.cut.tool_diameter_mm);
  if (a.protrusion.stepover_mm > 0 && stepped) {
    const double d = *stepped;
    check_range("--stepover", a.protrusion.stepover_mm,
                Range{kMinStepoverShare * d, d / 2,
                      std::string("mm (from 5 % of the ") + (vcarve ? "--flat-bottom" : "--tool-diameter") +
                          " to its radius)"});
  }
  if (!a.tool_image.empty() && !(a.pixel_size_um > 0))
    throw InputError("--tool-image needs --pixel-size UM (micrometres per pixel)");
}

VCarveSettings vcarve_settings(const GcodeArgs& a) {
  VCarveSettings v;
  if (a.bit_angle_deg) v.bit_angle_deg = *a.bit_angle_deg;
  if (a.max_depth_mm) v.max_depth_mm = *a.max_depth_mm;
  if (a.flat_bottom_mm) v.flat_bottom_mm = *a.flat_bottom_mm;
  if (a.carve_tolerance_mm) v.tolerance_mm = *a.carve_tolerance_mm;
  v.stepover_mm = a.protrusion.stepover_mm;
  v.even_odd = a.fill_rule == "evenodd";
  return v;
}

MachineEnvelope machine_envelope(const GcodeArgs& a) {
  MachineEnvelope env;
  if (!a.stock.empty()) env.stock = parse_stock(a.stock);
  if (!a.travel.empty()) std::tie(env.travel_x_mm, env.travel_y_mm) = parse_travel(a.travel);
  return env;
}

}  // namespace mark::cli
