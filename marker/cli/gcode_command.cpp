// `marker gcode TEXT [layout options] [--char-spacing PCT] [--word-spacing PCT]
//  --mode depression|protrusion|v-carve --tool-diameter MM --depth MM [--depth-per-pass MM]
//  [--bit-angle DEG] [--max-depth MM] [--flat-bottom MM --cleanup-output FILE] [--carve-tolerance MM]
//  [--dialect linuxcnc|fanuc|plain] [--units mm|in] [--safe-z MM] [--feed MM/MIN] [--plunge-feed MM/MIN]
//  [--spindle RPM] [--header LINE]... [--footer LINE]... [--arc-tolerance MM] [--ellipse-chords] [--m2]
//  [--stroke-width MM] [--margin MM] [--stepover MM] [--cutter-comp] [--tool-image FILE --pixel-size UM]
//  [--stock W,H|X,Y,W,H] [--travel X,Y] -o FILE.ngc [--preview FILE.svg] [--json] [--quiet]`:
//  CNC engraving G-code for the same text and fitting as the laser, checked against the machine's
//  envelope instead of a galvo field.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "fonts/utf8.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/console_progress.hpp"
#include "marker/cli/gcode_options.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/cli/print.hpp"
#include "marker/cli/tool_measure_report.hpp"
#include "marker/cnc/depression.hpp"
#include "marker/cnc/gcode_writer.hpp"
#include "marker/cnc/letter_contacts.hpp"
#include "marker/cnc/stroke_gaps.hpp"
#include "marker/cnc/tool/tool_measure.hpp"
#include "marker/cnc/toolpath_preview.hpp"
#include "marker/layout/figure_json.hpp"
#include "marker/limits/cnc_settings.hpp"
#include "marker/output/output_file.hpp"

namespace mark::cli {
namespace {

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

// A depression cut with a tool at least as wide as the gap between two strokes cuts them into one
// groove.
void warn_narrow_gap(const Figure& figure, double tool_mm, nlohmann::json& out, nlohmann::json& warnings,
                     const Progress& progress) {
  const std::optional<StrokeGap> gap = narrowest_stroke_gap(figure, tool_mm, progress);
  out["narrowest_gap_mm"] = gap ? nlohmann::json(gap->width_mm) : nlohmann::json(nullptr);
  if (!gap) return;
  const Point at = (gap->a + gap->b) / 2;
  warn(warnings, format("the tool (%g mm) is at least as wide as the narrowest gap between strokes, %.4f mm "
                        "around (%.3f, %.3f) mm: the grooves on either side run into one; use a narrower tool, "
                        "or raise --height or --char-spacing",
                        tool_mm, gap->width_mm, at.x(), at.y()));
}

nlohmann::json vcarve_json(const VCarveResult& r, const VCarveSettings& v, const GcodeArgs& a) {
  return {{"bit_angle_deg", v.bit_angle_deg},
          {"carve_tolerance_mm", v.tolerance_mm},
          {"depth_limit_mm", r.depth_limit_mm},
          {"deepest_mm", r.deepest_mm},
          {"flat_area_mm2", r.flat_area_mm2},
          {"uncleaned_area_mm2", r.uncleaned_area_mm2},
          {"axis_edges", r.axis_edges},
          {"pruned_edges", r.pruned_edges},
          {"flat_bottom_mm", v.flat_bottom_mm > 0 ? nlohmann::json(v.flat_bottom_mm) : nlohmann::json(nullptr)},
          {"cleanup_output", a.cleanup_output.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.cleanup_output)}};
}

void warn_flat(const VCarveResult& r, const VCarveSettings& v, nlohmann::json& warnings) {
  if (r.uncleaned_area_mm2 <= 1e-6) return;
  if (v.flat_bottom_mm > 0)
    warn(warnings, format("the %g mm end mill cannot reach %.4f mm² of the flat bottoms (corners narrower than "
                          "it): a smaller --flat-bottom tool reaches more",
                          v.flat_bottom_mm, r.uncleaned_area_mm2));
  else
    warn(warnings, format("the depth limit of %.4f mm leaves %.4f mm² of flat bottoms that only the V-bit's tip "
                          "crosses: clear them with --flat-bottom MM --cleanup-output FILE, or allow a deeper "
                          "--max-depth",
                          r.depth_limit_mm, r.flat_area_mm2));
}

int run_gcode(GcodeArgs& a) {
  check_gcode_args(a);
  const bool protrusion = a.protrusion_mode(), vcarve = a.vcarve_mode();
  validate(a.gcode);  // header and footer lines against the dialect, before any work
  const MachineEnvelope envelope = machine_envelope(a);
  check_standard_output({{"--output", &a.output}, {"--cleanup-output", &a.cleanup_output}, {"--preview", &a.preview}},
                        a.json);
  check_output_path("--output", a.output);
  if (!a.cleanup_output.empty()) {
    check_output_path("--cleanup-output", a.cleanup_output);
    if (a.cleanup_output == a.output) throw InputError("--cleanup-output must differ from --output");
  }
  if (!a.preview.empty()) check_output_path("--preview", a.preview, {".svg", ".png"});
  ConsoleProgress progress = command_progress(a.quiet || a.json);

  // The base point lies within the machine's travel.
  const double reach = std::max(envelope.travel_x_mm, envelope.travel_y_mm);
  const Range in_travel{-reach, reach, "mm (within the --travel, " + format_number(envelope.travel_x_mm) + " x " +
                                           format_number(envelope.travel_y_mm) + " mm)"};
  const LaidOutText laid = lay_out_text(a.text, a.layout, to_layout_options(a.layout, in_travel));
  nlohmann::json out = {{"output", a.output},
                        {"mode", a.mode},
                        {"dialect", to_string(a.gcode.dialect)},
                        {"units", a.gcode.units == Units::inch ? "inch" : "mm"},
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
  VCarveResult carve;
  const VCarveSettings vs = vcarve_settings(a);
  CutFootprint footprint{a.cut.tool_diameter_mm / 2, 0};
  if (protrusion) {
    res = protrusion_toolpath(laid.figure, a.cut, a.protrusion, progress);
    tp = res.toolpath;
    warn_touching(laid, res.stroke_width_mm, warnings);
    warn_uncut(res, warnings);
    out["protrusion"] = protrusion_json(res, a.protrusion.cutter_comp);
  } else if (vcarve) {
    carve = vcarve_toolpath(laid.figure, a.cut, vs, progress);
    tp = carve.toolpath;
    footprint.v_half_angle_rad = carve.half_angle_rad;
    warn_flat(carve, vs, warnings);
    out["vcarve"] = vcarve_json(carve, vs, a);
  } else {
    tp = depression_toolpath(laid.figure, a.cut, progress);
    warn_narrow_gap(laid.figure, a.cut.tool_diameter_mm, out, warnings, progress);
  }
  // The machine's envelope: every cut on the stock, the whole program within the travel.
  const ToolpathExtent extent = toolpath_extent(tp, footprint);
  require_within(extent, envelope,
                 "move the text with --x, --y or --align, lower --height, or give a larger --stock or --travel");
  GcodeStats st;
  const std::string program = write_gcode(tp, a.gcode, &st, progress);
  std::string cleanup_program;
  GcodeStats cleanup_stats;
  if (!a.cleanup_output.empty()) {
    GcodeOptions co = a.gcode;
    co.title = "marker v-carve clean-up, " + format_number(vs.flat_bottom_mm) + " mm end mill: " + unescape_text(a.text);
    cleanup_program = write_gcode(carve.cleanup, co, &cleanup_stats, progress);
  }
  // Everything is computed: the files go out whole, the program first.
  progress.writing_files();
  write_file_whole(a.output, program);
  if (!a.cleanup_output.empty()) write_file_whole(a.cleanup_output, cleanup_program);
  if (!a.preview.empty())
    write_toolpath_preview(laid.figure, tp, a.cut.tool_diameter_mm, protrusion ? &res : nullptr, a.preview,
                           vcarve ? &carve : nullptr);

  const RapidTravel travel = rapid_travel(tp);
  out["lines"] = st.lines;
  out["rapid_moves"] = st.rapids;
  out["feed_moves"] = st.feeds;
  out["arc_moves"] = st.arcs;
  out["subprograms"] = tp.subs.size();
  out["calls"] = st.calls;
  out["inlined"] = st.inlined;
  out["max_arc_radius_error_mm"] = st.max_arc_radius_error_mm;
  out["rapid_travel_mm"] = travel.xy_mm;
  out["retracts"] = travel.retracts;
  out["cut_bounds_mm"] = box_json(extent.cuts);
  out["program_bounds_mm"] = box_json(extent.moves);
  out["stock_mm"] = envelope.stock ? box_json(*envelope.stock) : nlohmann::json(nullptr);
  out["travel_mm"] = {{"x", envelope.travel_x_mm}, {"y", envelope.travel_y_mm}};
  if (vcarve) out["vcarve"]["cleanup_lines"] = cleanup_stats.lines;
  out["preview"] = a.preview.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.preview);
  out["warnings"] = warnings;
  if (a.json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::cout << format("%s: %zu lines, %zu rapid, %zu feed, %zu arc moves; %zu subprograms, %zu calls, %zu inlined\n",
                      a.output.c_str(), st.lines, st.rapids, st.feeds, st.arcs, tp.subs.size(), st.calls,
                      st.inlined);
  std::cout << format("rapid travel %.1f mm, %zu retracts; cuts span x %.3f to %.3f, y %.3f to %.3f mm\n",
                      travel.xy_mm, travel.retracts, extent.cuts.min.x(), extent.cuts.max.x(), extent.cuts.min.y(),
                      extent.cuts.max.y());
  if (protrusion) {
    std::cout << format("plate %.3f x %.3f mm at (%.3f, %.3f); %zu pocket loops per pass, step-over %.3f mm\n",
                        res.plate.width(), res.plate.height(), res.plate.min.x(), res.plate.min.y(), res.loops,
                        res.stepover_mm);
    if (a.protrusion.cutter_comp)
      std::cout << format("cutter compensation: %zu walls under G41, %zu without room for a lead move cut as "
                          "tool-centre loops\n",
                          res.comp_walls, res.walls_without_comp);
  }
  if (vcarve) {
    std::cout << format("v-carve: %g° bit, deepest %.4f mm (limit %.4f mm), %.4f mm² flat bottom\n", vs.bit_angle_deg,
                        carve.deepest_mm, carve.depth_limit_mm, carve.flat_area_mm2);
    if (!a.cleanup_output.empty())
      std::cout << format("%s: %zu lines for the %g mm end mill\n", a.cleanup_output.c_str(), cleanup_stats.lines,
                          vs.flat_bottom_mm);
  }
  if (!a.preview.empty()) std::cout << "preview: " << a.preview << "\n";
  return 0;
}

}  // namespace

Command make_gcode_command() {
  auto a = std::make_shared<GcodeArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand(
            "gcode", "CNC engraving G-code: depression (engraved), protrusion (raised) or v-carved letters");
        add_gcode_options(*sub, *a);
        return sub;
      },
      [a] { return run_gcode(*a); });
}

}  // namespace mark::cli
