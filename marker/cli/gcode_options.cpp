#include "marker/cli/gcode_options.hpp"

#include <tuple>

#include "base/error.hpp"
#include "marker/cli/machine_values.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/tool_measure_report.hpp"
#include "marker/limits/cnc_limits.hpp"

namespace mark::cli {
namespace {

// Engraving cutters run from 0.1 to 12 mm, feeds from a few to a few thousand mm/min; the ranges
// leave room on both sides and keep every number a controller can be given.
const Range kToolRange = length_range(0.01, 50);
const Range kDepthRange = length_range(0.001, 50);
const Range kDepthPerPassRange{0.001, 50, "mm", false, true};
const Range kSafeZRange = length_range(0.1, 1000);
const Range kFeedRange{1, 100000, "mm/min"};
const Range kSpindleRange{1, 200000, "rpm", false, true};
// Below 1 µm the tolerance is finer than the program's 4 decimals can write.
const Range kArcToleranceRange = length_range(0.001, 1);
const Range kStrokeWidthRange{0.01, 100, "mm", false, true};
const Range kMarginRange{0.01, 1000, "mm", false, true};
const Range kStepoverRange{0.001, 25, "mm", false, true};
// Pocket loops closer than 5 % of the tool diameter only multiply the cutting time.
constexpr double kMinStepoverShare = 0.05;

}  // namespace

void add_gcode_options(CLI::App& sub, GcodeArgs& a) {
  sub.add_option("text", a.text, "text to engrave (UTF-8; \\n starts a new line)")->required();
  add_layout_options(sub, a.layout, /*galvo_field=*/false);
  add_spacing_options(sub, a.layout);
  sub.add_option("--mode", a.mode,
                 "depression: tool centre on the strokes; protrusion: pocket around the letters; v-carve: V-bit "
                 "on the medial axis of outline letters")
      ->check(CLI::IsMember({"depression", "protrusion", "v-carve"}))
      ->capture_default_str();
  add_ranged_option(sub, "--tool-diameter", a.cut.tool_diameter_mm, "cutter diameter (v-carve: the V-bit's), mm", kToolRange)
      ->capture_default_str();
  add_ranged_option(sub, "--depth", a.cut.depth_mm, "engraving depth below the surface, mm", kDepthRange)
      ->capture_default_str();
  add_ranged_option(sub, "--depth-per-pass", a.cut.depth_per_pass_mm, "at most this deep per pass, mm (0: one pass)",
                    kDepthPerPassRange)
      ->capture_default_str();
  add_ranged_option(sub, "--safe-z", a.cut.safe_z_mm, "height for rapid moves, mm", kSafeZRange)->capture_default_str();
  add_ranged_option(sub, "--feed", a.cut.feed_mm_min, "cutting feed, mm/min", kFeedRange)->capture_default_str();
  add_ranged_option(sub, "--plunge-feed", a.cut.plunge_feed_mm_min, "plunge feed, mm/min", kFeedRange)
      ->capture_default_str();
  add_ranged_option(sub, "--spindle", a.gcode.spindle_rpm, "spindle speed, rpm (0: no M3/M5)", kSpindleRange)
      ->capture_default_str();
  sub.add_option("--dialect", a.dialect, "linuxcnc (o-word subprograms), fanuc (O/M98/M99), plain (grbl, inlined)")
      ->capture_default_str();
  sub.add_option("--units", a.units, "output units: mm (G21) or in (G20); every length given is in mm")
      ->capture_default_str();
  sub.add_option("--header", a.gcode.header, "line after the program's modal preamble (repeatable)")->allow_extra_args(false);
  sub.add_option("--footer", a.gcode.footer, "line before the program end (repeatable)")->allow_extra_args(false);
  sub.add_option("--title", a.gcode.title, "comment at the top of the program (default: the mode and the text)");
  sub.add_flag("--m2", a.m2, "end with M2 instead of M30");
  add_ranged_option(sub, "--arc-tolerance", a.cut.arcs.tolerance_mm,
                    "how far arc splines of elliptical arcs may leave the curve, mm", kArcToleranceRange)
      ->capture_default_str();
  sub.add_flag("--ellipse-chords", a.cut.arcs.ellipse_chords, "cut elliptical arcs as G01 chords instead of biarcs");
  add_ranged_option(sub, "--stroke-width", a.protrusion.stroke_width_mm,
                    "protrusion: width of the raised strokes, mm (0: tool diameter)", kStrokeWidthRange)
      ->capture_default_str();
  add_ranged_option(sub, "--margin", a.protrusion.margin_mm,
                    "protrusion: letters to boundary rectangle, mm (0: 2 × tool diameter)", kMarginRange)
      ->capture_default_str();
  add_ranged_option(sub, "--stepover", a.protrusion.stepover_mm,
                    "protrusion and v-carve clean-up: between pocket loops, mm (0: 40 % of the tool diameter; "
                    "else 5 % of the diameter to its radius)",
                    kStepoverRange)
      ->capture_default_str();
  sub.add_flag("--cutter-comp", a.protrusion.cutter_comp,
               "protrusion: program the walls as part contours with G41 and the tool diameter in D");
  sub.add_option("--tool-image", a.tool_image,
                 "shadow image of the tool (PNG or PGM): its measured diameter replaces --tool-diameter in the offsets");
  add_ranged_option(sub, "--pixel-size", a.pixel_size_um, "tool image: micrometres per pixel", kPixelSizeRange);
  add_ranged_option(sub, "--bit-angle", a.bit_angle_deg, "v-carve: included angle of the V-bit, degrees (default 60)",
                    kBitAngleRange);
  add_ranged_option(sub, "--max-depth", a.max_depth_mm,
                    "v-carve: deepest cut, mm; deeper places get a flat bottom (default: what the bit's diameter "
                    "can cut)",
                    kMaxDepthRange);
  add_ranged_option(sub, "--flat-bottom", a.flat_bottom_mm,
                    "v-carve: diameter of the end mill that clears the flat bottoms, mm (needs --cleanup-output)",
                    kFlatBottomRange);
  sub.add_option("--cleanup-output", a.cleanup_output, "v-carve: G-code file for the flat-bottom end mill");
  add_ranged_option(sub, "--carve-tolerance", a.carve_tolerance_mm,
                    "v-carve: how far the carve may stray from the exact medial axis, mm (default 0.002)",
                    kCarveToleranceRange);
  sub.add_option("--fill-rule", a.fill_rule,
                 "v-carve: inside of overlapping outlines: nonzero (TrueType, CFF; default) or evenodd");
  sub.add_option("--stock", a.stock,
                 "the stock: W,H with its lower-left corner at X0 Y0, or X,Y,W,H; every cut must lie on it (mm)");
  sub.add_option("--travel", a.travel, "the machine's travel X,Y: the largest the program may span (mm; default 10000,10000)");
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
    if (!a.fill_rule.empty() && a.fill_rule != "nonzero" && a.fill_rule != "evenodd")
      throw InputError("--fill-rule '" + a.fill_rule + "' is not one of nonzero, evenodd");
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
