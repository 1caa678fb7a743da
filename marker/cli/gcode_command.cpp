// `marker gcode TEXT [layout options] --mode depression|protrusion --tool-diameter MM --depth MM
//  [--depth-per-pass MM] [--dialect linuxcnc|fanuc|plain] [--units mm|inch] [--safe-z MM]
//  [--feed MM/MIN] [--plunge-feed MM/MIN] [--spindle RPM] [--header LINE]... [--footer LINE]...
//  [--arc-tolerance MM] [--ellipse-chords] [--m2] [--stroke-width MM] [--margin MM]
//  [--stepover MM] [--cutter-comp] [--tool-image FILE --pixel-size UM] -o FILE.ngc
//  [--preview FILE.svg] [--json]`: CNC engraving G-code for the same text and fitting as the laser.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "fonts/utf8.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/cli/print.hpp"
#include "marker/cli/tool_measure_report.hpp"
#include "marker/cnc/depression.hpp"
#include "marker/cnc/gcode_writer.hpp"
#include "marker/cnc/letter_contacts.hpp"
#include "marker/cnc/protrusion.hpp"
#include "marker/cnc/tool/tool_measure.hpp"
#include "marker/cnc/toolpath_preview.hpp"
#include "marker/limits/cnc_settings.hpp"
#include "marker/output/output_file.hpp"

namespace mark::cli {
namespace {

// Pocket loops closer than 5 % of the tool diameter only multiply the cutting time.
constexpr double kMinStepoverShare = 0.05;

struct GcodeArgs {
  std::string text;
  LayoutArgs layout;
  std::string mode;
  CutSettings cut;
  ProtrusionSettings protrusion;
  GcodeOptions gcode;
  std::string dialect;
  std::string units;
  bool m2 = false;
  std::string tool_image;
  double pixel_size_um = 0;
  std::string output;
  std::string preview;
  bool json = false;
};

// The checks that need more than one option; single values were checked while parsing.
void check_settings(const GcodeArgs& a, bool protrusion) {
  if (a.protrusion.cutter_comp && !protrusion)
    throw InputError("--cutter-comp: only protrusion walls can be compensated by the control");
  if (a.protrusion.cutter_comp && a.gcode.dialect == Dialect::plain)
    throw InputError("--cutter-comp needs --dialect linuxcnc or fanuc: grbl has no G41/G42");
  if (a.protrusion.stepover_mm > 0) {
    const double d = a.cut.tool_diameter_mm;
    check_range("--stepover", a.protrusion.stepover_mm,
                Range{kMinStepoverShare * d, d / 2,
                      "mm (from 5 % of the --tool-diameter to its radius)"});
  }
  if (!a.tool_image.empty() && !(a.pixel_size_um > 0))
    throw InputError("--tool-image needs --pixel-size UM (micrometres per pixel)");
}

// One warning per line on stderr, and the same text in the JSON.
void warn(nlohmann::json& warnings, const std::string& text) {
  std::cerr << "marker: warning: " << text << "\n";
  warnings.push_back(text);
}

void warn_touching(const LaidOutText& laid, double stroke_width_mm, nlohmann::json& warnings) {
  const std::vector<LetterContact> touching = touching_letters(laid.figure, stroke_width_mm);
  if (touching.empty()) return;
  const LetterContact& c = touching.front();
  const std::string a = encode_utf8(laid.figure.glyphs[c.first].code_point);
  const std::string b = encode_utf8(laid.figure.glyphs[c.second].code_point);
  std::string text = format("raised letters '%s' and '%s' run into each other at stroke width %g mm "
                            "(%.4f mm² shared around (%.3f, %.3f) mm)",
                            a.c_str(), b.c_str(), stroke_width_mm, c.area_mm2, c.at.x(), c.at.y());
  if (touching.size() > 1) text += format(", and %zu more pairs", touching.size() - 1);
  warn(warnings, text + "; raise --gap or --height, or lower --stroke-width");
}

void warn_uncut(const ProtrusionResult& res, nlohmann::json& warnings) {
  if (res.uncut.empty()) return;
  double total = 0, largest = 0;
  const UncutRegion* big = &res.uncut.front();
  for (const UncutRegion& u : res.uncut) {
    total += u.area_mm2;
    if (u.area_mm2 > largest) largest = u.area_mm2, big = &u;
  }
  warn(warnings, format("%zu places narrower than the tool stay uncut (%.4f mm² in all, largest %.4f mm² "
                        "around (%.3f, %.3f) mm)",
                        res.uncut.size(), total, largest, big->bounds.center().x(), big->bounds.center().y()));
}

nlohmann::json protrusion_json(const ProtrusionResult& res, bool cutter_comp) {
  nlohmann::json uncut = nlohmann::json::array();
  for (const UncutRegion& u : res.uncut)
    uncut.push_back({{"area_mm2", u.area_mm2}, {"x_mm", u.bounds.center().x()}, {"y_mm", u.bounds.center().y()}});
  nlohmann::json j = {{"plate_mm",
                       {{"x_min", res.plate.min.x()}, {"y_min", res.plate.min.y()},
                        {"x_max", res.plate.max.x()}, {"y_max", res.plate.max.y()}}},
                      {"stroke_width_mm", res.stroke_width_mm},
                      {"stepover_mm", res.stepover_mm},
                      {"pocket_loops", res.loops},
                      {"uncut", std::move(uncut)}};
  if (cutter_comp) {
    j["comp_walls"] = res.comp_walls;
    j["walls_without_comp"] = res.walls_without_comp;
  }
  return j;
}

int run_gcode(GcodeArgs& a) {
  a.gcode.dialect = parse_dialect(a.dialect);
  a.gcode.units = parse_units(a.units);
  a.gcode.end_with_m30 = !a.m2;
  const bool protrusion = a.mode == "protrusion";
  check_settings(a, protrusion);
  validate(a.gcode);  // header and footer lines against the dialect, before any work
  check_standard_output({{"--output", &a.output}, {"--preview", &a.preview}}, a.json);
  check_output_path("--output", a.output);
  if (!a.preview.empty()) check_output_path("--preview", a.preview, {".svg", ".png"});

  const LaidOutText laid = build_figure(a.text, a.layout);
  nlohmann::json out = {{"output", a.output},
                        {"mode", a.mode},
                        {"dialect", to_string(a.gcode.dialect)},
                        {"units", a.units == "in" ? "inch" : a.units},
                        {"text", unescape_text(a.text)},
                        {"font", a.layout.font},
                        {"height_mm", a.layout.height_mm}};
  nlohmann::json warnings = nlohmann::json::array();
  const double nominal = a.cut.tool_diameter_mm;
  if (!a.tool_image.empty()) {
    // Tool form compensation: the measured radius replaces the nominal one in every offset.
    ToolMeasureOptions mo;
    mo.pixel_size_um = a.pixel_size_um;
    mo.nominal_diameter_mm = nominal;
    const ToolMeasurement m = measure_tool(read_gray_image(a.tool_image), mo, a.tool_image);
    out["tool_measured"] = tool_measurement_json(m, mo);
    if (!a.json)
      std::cout << format("tool: measured diameter %.4f mm (nominal %.4f mm), form deviation %.4f mm\n",
                          m.diameter_mm, nominal, m.form_deviation_mm);
    a.cut.tool_diameter_mm = m.diameter_mm;
    // The letters keep the width they were designed with: the nominal tool's.
    if (!(a.protrusion.stroke_width_mm > 0)) a.protrusion.stroke_width_mm = nominal;
  }
  out["tool_diameter_mm"] = a.cut.tool_diameter_mm;
  // The title carries the text line by line; the writer wraps it to the dialect's line length.
  if (a.gcode.title.empty()) a.gcode.title = "marker " + a.mode + ": " + unescape_text(a.text);

  Toolpath tp;
  ProtrusionResult res;
  if (protrusion) {
    res = protrusion_toolpath(laid.figure, a.cut, a.protrusion);
    tp = res.toolpath;
    warn_touching(laid, res.stroke_width_mm, warnings);
    warn_uncut(res, warnings);
    out["protrusion"] = protrusion_json(res, a.protrusion.cutter_comp);
  } else {
    tp = depression_toolpath(laid.figure, a.cut);
  }
  GcodeStats st;
  const std::string program = write_gcode(tp, a.gcode, &st);
  write_file_whole(a.output, program);
  if (!a.preview.empty())
    write_toolpath_preview(laid.figure, tp, a.cut.tool_diameter_mm, protrusion ? &res : nullptr, a.preview);

  out["lines"] = st.lines;
  out["rapid_moves"] = st.rapids;
  out["feed_moves"] = st.feeds;
  out["arc_moves"] = st.arcs;
  out["subprograms"] = tp.subs.size();
  out["calls"] = st.calls;
  out["inlined"] = st.inlined;
  out["max_arc_radius_error_mm"] = st.max_arc_radius_error_mm;
  out["preview"] = a.preview.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.preview);
  out["warnings"] = warnings;
  if (a.json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::cout << format("%s: %zu lines, %zu rapid, %zu feed, %zu arc moves; %zu subprograms, %zu calls, %zu inlined\n",
                      a.output.c_str(), st.lines, st.rapids, st.feeds, st.arcs, tp.subs.size(), st.calls,
                      st.inlined);
  if (protrusion) {
    std::cout << format("plate %.3f x %.3f mm at (%.3f, %.3f); %zu pocket loops per pass, step-over %.3f mm\n",
                        res.plate.width(), res.plate.height(), res.plate.min.x(), res.plate.min.y(), res.loops,
                        res.stepover_mm);
    if (a.protrusion.cutter_comp)
      std::cout << format("cutter compensation: %zu walls under G41, %zu without room for a lead move cut as "
                          "tool-centre loops\n",
                          res.comp_walls, res.walls_without_comp);
  }
  if (!a.preview.empty()) std::cout << "preview: " << a.preview << "\n";
  return 0;
}

}  // namespace

Command make_gcode_command() {
  auto a = std::make_shared<GcodeArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("gcode", "CNC engraving G-code: depression (engraved) or protrusion (raised) letters");
        sub->add_option("text", a->text, "text to engrave (UTF-8; \\n starts a new line)")->required();
        add_layout_options(*sub, a->layout);
        add_setting(*sub, kCncMode, a->mode);
        add_setting(*sub, kToolDiameter, a->cut.tool_diameter_mm);
        add_setting(*sub, kDepth, a->cut.depth_mm);
        add_setting(*sub, kDepthPerPass, a->cut.depth_per_pass_mm);
        add_setting(*sub, kSafeZ, a->cut.safe_z_mm);
        add_setting(*sub, kFeed, a->cut.feed_mm_min);
        add_setting(*sub, kPlungeFeed, a->cut.plunge_feed_mm_min);
        add_setting(*sub, kSpindle, a->gcode.spindle_rpm);
        add_setting(*sub, kDialect, a->dialect);
        add_setting(*sub, kUnits, a->units);
        add_setting(*sub, kHeader, a->gcode.header)->allow_extra_args(false);
        add_setting(*sub, kFooter, a->gcode.footer)->allow_extra_args(false);
        add_setting(*sub, kTitle, a->gcode.title);
        add_setting(*sub, kM2, a->m2);
        add_setting(*sub, kArcTolerance, a->cut.arcs.tolerance_mm);
        add_setting(*sub, kEllipseChords, a->cut.arcs.ellipse_chords);
        add_setting(*sub, kStrokeWidth, a->protrusion.stroke_width_mm);
        add_setting(*sub, kMargin, a->protrusion.margin_mm);
        add_setting(*sub, kStepover, a->protrusion.stepover_mm);
        add_setting(*sub, kCutterComp, a->protrusion.cutter_comp);
        sub->add_option("--tool-image", a->tool_image, "shadow image of the tool (PNG or PGM): its measured diameter replaces --tool-diameter in the offsets");
        add_setting(*sub, kPixelSize, a->pixel_size_um);
        sub->add_option("-o,--output", a->output, "G-code file to write")->required();
        sub->add_option("--preview", a->preview, "draw the toolpath to FILE.svg or FILE.png");
        sub->add_flag("--json", a->json, "print the result as one JSON object (docs/json.md)");
        return sub;
      },
      [a] { return run_gcode(*a); });
}

}  // namespace mark::cli
