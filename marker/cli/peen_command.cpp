// `marker peen TEXT [--font 5x7|7x9|10x16|builtin|FILE] [layout options] [--planner ...]
//  [--window WxH] [--pitch MM] [--preview FILE.svg] [--json] [--quiet] [--compare] [-o FILE.csv|FILE.ngc]
//  [gantry options]`: plans the needle path of a pin marker and times it on the simulated gantry.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/console_progress.hpp"
#include "marker/cli/gantry_options.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/cli/print.hpp"
#include "marker/layout/figure_json.hpp"
#include "marker/limits/peen_settings.hpp"
#include "marker/cli/print.hpp"
#include "marker/output/output_file.hpp"
#include "marker/peen/dot_fonts.hpp"
#include "marker/peen/dot_layout.hpp"
#include "marker/peen/gantry_run.hpp"
#include "marker/peen/peen_json.hpp"
#include "marker/peen/peen_preview.hpp"
#include "marker/peen/plan_export.hpp"
#include "marker/peen/planners.hpp"

namespace mark::cli {
namespace {

struct PeenArgs {
  std::string text;
  LayoutArgs layout;
  GantryArgs gantry;
  std::string planner;
  std::string window;  // "WxH" in mm; empty: the dots' bounding box
  std::optional<double> pitch_mm;
  std::string preview;
  std::string output;
  bool json = false;
  bool quiet = false;
  bool compare = false;
  bool block_straight = false;
};

// A plan holds at most this many dots: a 17-character VIN in the 10x16 font has about 1,400 and
// a 100-character stroke-font text at the default pitch about 4,000; 50,000 plan and simulate in
// about a second.
constexpr std::size_t kMaxDots = 50'000;
// Neighbouring dots at least this many motor steps apart: with the strokes' dots kept half a
// pitch apart, 4 steps is the least that keeps two dots from rounding to the same step position.
constexpr double kMinPitchSteps = 4;

// "63x38" → 63 × 38 mm.
Box parse_window(const std::string& s, double field_mm) {
  const std::string option = "--window '" + s + "'";
  const std::vector<double> v = parse_numbers("--window", s, "xX", 2, "WIDTHxHEIGHT in millimetres, e.g. 63x38");
  const Range in_field = positive_up_to(field_mm, "mm (the --field is " + format_number(field_mm) + " mm)");
  check_range(option + " width", v[0], in_field);
  check_range(option + " height", v[1], in_field);
  return centred_window(v[0], v[1]);
}

// The finest dot spacing the gantry can strike apart: kMinPitchSteps of its coarser axis.
double min_pitch_mm(const GantryConfig& g) {
  return kMinPitchSteps / std::min(g.x.steps_per_mm, g.y.steps_per_mm);
}

DotText build_dots(const PeenArgs& a, const GantryConfig& gantry) {
  const std::string text = unescape_text(a.text);
  const std::string steps = format_number(kMinPitchSteps) + " motor steps at --steps-per-mm " +
                            format_number(std::min(gantry.x.steps_per_mm, gantry.y.steps_per_mm));
  DotText dots;
  if (const DotFont* font = find_dot_font(a.layout.font)) {
    if (a.pitch_mm) throw InputError("--pitch: the " + a.layout.font + " dot font's pitch follows --height");
    // Rows are height / (rows − 1) apart, columns that times the width factor.
    const double spacing = a.layout.height_mm / (font->rows() - 1) * std::min(1.0, a.layout.width_factor);
    if (spacing < min_pitch_mm(gantry))
      throw InputError("--height " + format_number(a.layout.height_mm) + ": the " + a.layout.font +
                       " dots would be " + format_number(spacing) + " mm apart, closer than " +
                       format_number(min_pitch_mm(gantry)) + " mm (" + steps + "); raise --height or --steps-per-mm");
    dots = layout_dot_text(text, *font, to_layout_options(a.layout));
  } else {
    // Any stroke font: "continuous" dots along the strokes.
    const double pitch = a.pitch_mm ? *a.pitch_mm : a.layout.height_mm / 10;
    check_range(a.pitch_mm ? "--pitch" : "--pitch (default --height / 10)", pitch,
                Range{min_pitch_mm(gantry), a.layout.height_mm, "mm (from " + steps + " up to the --height)"});
    const LaidOutText laid = build_figure(a.text, a.layout);
    // Counted before any dot is made: a fine pitch on a long text must not run for minutes.
    const double estimate = laid.figure.mark_length_mm() / pitch;
    if (estimate > kMaxDots)
      throw InputError("--pitch " + format_number(pitch) + " mm gives about " + format_number(std::round(estimate)) +
                       " dots along " + format_number(laid.figure.mark_length_mm()) +
                       " mm of strokes, more than a plan may hold (" + std::to_string(kMaxDots) +
                       "); raise --pitch or shorten the text");
    dots = dots_along_strokes(laid.figure, pitch);
  }
  if (dots.dots.empty()) throw InputError("text '" + a.text + "' has no dots to strike");
  if (dots.dots.size() > kMaxDots)
    throw InputError("text '" + a.text + "' has " + std::to_string(dots.dots.size()) +
                     " dots, more than a plan may hold (" + std::to_string(kMaxDots) + "); shorten the text");
  require_inside(dots.bounds(), Field{a.layout.field_mm}, "the dot text", kFieldRemedy);
  return dots;
}

void print_summary(const nlohmann::json& r) {
  print("%s planner: %zu dots, %zu characters\n", r["planner"].get<std::string>().c_str(),
        r["dots"].get<std::size_t>(), r["characters"].get<std::size_t>());
  print("time %.3f s (%.3f s per character: moves %.3f s, strikes %.3f s)\n",
        r["time_s"].get<double>(), r["time_per_char_s"].get<double>(),
        r["move_time_s"].get<double>(), r["strike_time_s"].get<double>());
  print("travel %.1f mm, %zu moves, %zu direction reversals\n", r["travel_mm"].get<double>(),
        r["moves"].get<std::size_t>(), r["reversals"].get<std::size_t>());
}

void print_comparison(const nlohmann::json& rows) {
  const double snake = rows[0]["time_s"].get<double>();
  print("%-10s %10s %10s %9s %11s %7s %10s\n", "planner", "time_s", "s/char", "vs snake",
        "travel_mm", "moves", "reversals");
  for (const nlohmann::json& r : rows)
    print("%-10s %10.3f %10.3f %8.1f%% %11.1f %7zu %10zu\n",
          r["planner"].get<std::string>().c_str(), r["time_s"].get<double>(),
          r["time_per_char_s"].get<double>(), 100 * (1 - r["time_s"].get<double>() / snake),
          r["travel_mm"].get<double>(), r["moves"].get<std::size_t>(),
          r["reversals"].get<std::size_t>());
}

int run_peen(const PeenArgs& a) {
  check_standard_output({{"--output", &a.output}, {"--preview", &a.preview}}, a.json);
  if (!a.output.empty()) check_output_path("--output", a.output, kPlanExtensions);
  if (!a.preview.empty()) check_output_path("--preview", a.preview, {".svg", ".png"});
  ConsoleProgress progress = command_progress(a.quiet || a.json);
  const GantryConfig gantry = to_gantry(a.gantry);
  const DotText dots = build_dots(a, gantry);
  const Box window = a.window.empty() ? tight_window(dots) : parse_window(a.window, a.layout.field_mm);
  require_inside(window, Field{a.layout.field_mm}, "the marking window");
  const PeenSetup setup{window, gantry, !a.block_straight, &progress};
  const PlannerKind chosen = *parse_planner(a.planner);

  PeenPlan plan = plan_peen(dots, chosen, setup);
  const nlohmann::json result = run_to_json(plan, dots, run_plan(plan, gantry));
  nlohmann::json rows = nlohmann::json::array();
  if (a.compare)
    for (PlannerKind k : kAllPlanners) {
      if (k == chosen) {
        rows.push_back(result);
        continue;
      }
      const PeenPlan other = plan_peen(dots, k, setup);
      rows.push_back(run_to_json(other, dots, run_plan(other, gantry)));
    }

  progress.writing_files();
  if (!a.output.empty()) export_plan(a.output, plan, dots, gantry);
  if (!a.preview.empty()) write_peen_preview(dots, plan, window, a.preview);

  if (a.json) {
    nlohmann::json out = result;
    out["window_mm"] = box_json(window);
    out["pitch_mm"] = dots.pitch_mm;
    out["gantry"] = gantry_to_json(gantry);
    if (a.compare) out["compare"] = rows;
    std::cout << out.dump(2) << "\n";
  } else if (a.compare) {
    print_comparison(rows);
  } else {
    print_summary(result);
  }
  if (!a.output.empty()) std::cerr << "marker: wrote " << a.output << "\n";
  if (!a.preview.empty()) std::cerr << "marker: wrote " << a.preview << "\n";
  return 0;
}

}  // namespace

Command make_peen_command() {
  auto a = std::make_shared<PeenArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand(
            "peen", "plan a pin marker's needle path for the text and time it on the simulated gantry");
        sub->add_option("text", a->text, "text to mark (UTF-8; \\n starts a new line)")->required();
        add_layout_options(*sub, a->layout, kDotFont);
        // Centred on the field: a pin marker's text sits in the middle of its window, and a
        // 12-letter 5 mm line (60 mm) then fits the default field, which it does not starting at
        // the centre.
        a->layout.align = "center";
        add_setting(*sub, kPlanner, a->planner);
        add_setting(*sub, kWindow, a->window);
        add_setting(*sub, kPitch, a->pitch_mm);
        sub->add_flag("--compare", a->compare, "time all three planners side by side");
        sub->add_flag("--json", a->json, "print the result as JSON");
        sub->add_flag("--quiet", a->quiet, "no progress lines on stderr");
        sub->add_option("--preview", a->preview, "draw dots and needle path to FILE.svg or FILE.png");
        sub->add_option("-o,--output", a->output,
                        "write the plan as a move/strike list (FILE.csv) or G-code (FILE.ngc)");
        add_setting(*sub, kBlockStraight, a->block_straight);
        add_gantry_options(*sub, a->gantry);
        return sub;
      },
      [a] { return run_peen(*a); });
}

}  // namespace mark::cli
