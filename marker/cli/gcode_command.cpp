// `marker gcode TEXT [layout options] --mode depression|protrusion --tool-diameter MM --depth MM
//  [--depth-per-pass MM] [--dialect linuxcnc|fanuc|plain] [--units mm|inch] [--safe-z MM]
//  [--feed MM/MIN] [--plunge-feed MM/MIN] [--spindle RPM] [--header LINE]... [--footer LINE]...
//  [--arc-tolerance MM] [--ellipse-chords] [--m2] [--stroke-width MM] [--margin MM]
//  [--stepover MM] [--cutter-comp] [--tool-image FILE --pixel-size UM] -o FILE.ngc
//  [--preview FILE.svg]`: CNC engraving G-code for the same text and fitting as the laser.
#include <cstdio>
#include <iostream>

#include "fonts/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/cnc/depression.hpp"
#include "marker/cnc/gcode_writer.hpp"
#include "marker/cnc/protrusion.hpp"
#include "marker/cnc/tool/tool_measure.hpp"
#include "marker/cnc/toolpath_preview.hpp"
#include "marker/io/atomic_file.hpp"

namespace mark::cli {
namespace {

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
  std::string output;
  std::string preview;
};

template <class... T>
void print(const char* format, T... values) {
  char line[512];
  std::snprintf(line, sizeof line, format, values...);
  std::cout << line;
}

int run_gcode(GcodeArgs& a) {
  if (a.mode != "depression" && a.mode != "protrusion")
    throw InputError("--mode '" + a.mode + "': expected depression or protrusion");
  a.gcode.dialect = parse_dialect(a.dialect);
  a.gcode.units = parse_units(a.units);
  a.gcode.end_with_m30 = !a.m2;
  const bool protrusion = a.mode == "protrusion";
  if (a.protrusion.cutter_comp && !protrusion)
    throw InputError("--cutter-comp: only protrusion walls can be compensated by the control");
  if (a.protrusion.cutter_comp && a.gcode.dialect == Dialect::plain)
    throw InputError("--cutter-comp needs --dialect linuxcnc or fanuc: grbl has no G41/G42");

  const LaidOutText laid = build_figure(a.text, a.layout);
  const double nominal = a.cut.tool_diameter_mm;
  if (!a.tool_image.empty()) {
    // Tool form compensation: the measured radius replaces the nominal one in every offset.
    if (!(a.pixel_size_um > 0)) throw InputError("--tool-image needs --pixel-size UM (micrometres per pixel)");
    ToolMeasureOptions mo;
    mo.pixel_size_um = a.pixel_size_um;
    mo.nominal_diameter_mm = nominal;
    const ToolMeasurement m = measure_tool(read_gray_image(a.tool_image), mo, a.tool_image);
    print("tool: measured diameter %.4f mm (nominal %.4f mm), form deviation %.4f mm\n", m.diameter_mm,
          nominal, m.form_deviation_mm);
    a.cut.tool_diameter_mm = m.diameter_mm;
    // The letters keep the width they were designed with: the nominal tool's.
    if (!(a.protrusion.stroke_width_mm > 0)) a.protrusion.stroke_width_mm = nominal;
  }
  if (a.gcode.title.empty()) a.gcode.title = "marker " + a.mode + ": " + a.text;

  Toolpath tp;
  ProtrusionResult res;
  if (protrusion) {
    res = protrusion_toolpath(laid.figure, a.cut, a.protrusion);
    tp = res.toolpath;
  } else {
    tp = depression_toolpath(laid.figure, a.cut);
  }
  GcodeStats st;
  const std::string program = write_gcode(tp, a.gcode, &st);
  write_file_atomically(a.output, program);
  print("%s: %zu lines, %zu rapid, %zu feed, %zu arc moves; %zu subprograms, %zu calls, %zu inlined\n",
        a.output.c_str(), st.lines, st.rapids, st.feeds, st.arcs, tp.subs.size(), st.calls, st.inlined);
  if (protrusion) {
    print("plate %.3f x %.3f mm at (%.3f, %.3f); %zu pocket loops per pass, step-over %.3f mm\n",
          res.plate.width(), res.plate.height(), res.plate.min.x(), res.plate.min.y(), res.loops,
          res.stepover_mm);
    if (a.protrusion.cutter_comp)
      print("cutter compensation: %zu walls under G41, %zu without room for a lead move cut as tool-centre loops\n",
            res.comp_walls, res.walls_without_comp);
    if (!res.uncut.empty()) {
      double total = 0, largest = 0;
      const UncutRegion* big = &res.uncut.front();
      for (const UncutRegion& u : res.uncut) {
        total += u.area_mm2;
        if (u.area_mm2 > largest) largest = u.area_mm2, big = &u;
      }
      std::cerr << "marker: warning: ";
      char line[256];
      std::snprintf(line, sizeof line,
                    "%zu places narrower than the tool stay uncut (%.4f mm² in all, largest %.4f mm² "
                    "around (%.3f, %.3f) mm)\n",
                    res.uncut.size(), total, largest, big->bounds.center().x(), big->bounds.center().y());
      std::cerr << line;
    }
  }
  if (!a.preview.empty()) {
    write_toolpath_preview(laid.figure, tp, a.cut.tool_diameter_mm, protrusion ? &res : nullptr, a.preview);
    print("preview: %s\n", a.preview.c_str());
  }
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
        sub->add_option("--mode", a->mode, "depression: tool centre on the strokes; protrusion: pocket around the letters")
            ->capture_default_str();
        sub->add_option("--tool-diameter", a->cut.tool_diameter_mm, "cutter diameter, mm")->capture_default_str();
        sub->add_option("--depth", a->cut.depth_mm, "engraving depth below the surface, mm")->capture_default_str();
        sub->add_option("--depth-per-pass", a->cut.depth_per_pass_mm, "at most this deep per pass, mm (0: one pass)")
            ->capture_default_str();
        sub->add_option("--safe-z", a->cut.safe_z_mm, "height for rapid moves, mm")->capture_default_str();
        sub->add_option("--feed", a->cut.feed_mm_min, "cutting feed, mm/min")->capture_default_str();
        sub->add_option("--plunge-feed", a->cut.plunge_feed_mm_min, "plunge feed, mm/min")->capture_default_str();
        sub->add_option("--spindle", a->gcode.spindle_rpm, "spindle speed, rpm (0: no M3/M5)")->capture_default_str();
        sub->add_option("--dialect", a->dialect, "linuxcnc (o-word subprograms), fanuc (O/M98/M99), plain (grbl, inlined)")
            ->capture_default_str();
        sub->add_option("--units", a->units, "output units: mm (G21) or inch (G20)")->capture_default_str();
        sub->add_option("--header", a->gcode.header, "line after the program's modal preamble (repeatable)")->allow_extra_args(false);
        sub->add_option("--footer", a->gcode.footer, "line before the program end (repeatable)")->allow_extra_args(false);
        sub->add_option("--title", a->gcode.title, "comment at the top of the program");
        sub->add_flag("--m2", a->m2, "end with M2 instead of M30");
        sub->add_option("--arc-tolerance", a->cut.arcs.tolerance_mm,
                        "how far arc splines of elliptical arcs may leave the curve, mm")
            ->capture_default_str();
        sub->add_flag("--ellipse-chords", a->cut.arcs.ellipse_chords, "cut elliptical arcs as G01 chords instead of biarcs");
        sub->add_option("--stroke-width", a->protrusion.stroke_width_mm, "protrusion: width of the raised strokes, mm (0: tool diameter)")
            ->capture_default_str();
        sub->add_option("--margin", a->protrusion.margin_mm, "protrusion: letters to boundary rectangle, mm (0: 2 × tool diameter)")
            ->capture_default_str();
        sub->add_option("--stepover", a->protrusion.stepover_mm, "protrusion: between pocket loops, mm (0: 40 % of the tool diameter)")
            ->capture_default_str();
        sub->add_flag("--cutter-comp", a->protrusion.cutter_comp,
                      "protrusion: program the walls as part contours with G41 and the tool diameter in D");
        sub->add_option("--tool-image", a->tool_image, "shadow image of the tool (PNG or PGM): its measured diameter replaces --tool-diameter in the offsets");
        sub->add_option("--pixel-size", a->pixel_size_um, "tool image: micrometres per pixel");
        sub->add_option("-o,--output", a->output, "G-code file to write")->required();
        sub->add_option("--preview", a->preview, "draw the toolpath to FILE.svg or FILE.png");
        return sub;
      },
      [a] { return run_gcode(*a); });
}

}  // namespace mark::cli
