// `marker peen TEXT [--font 5x7|7x9|10x16|builtin|FILE] [layout options] [--planner ...]
//  [--window WxH] [--pitch MM] [--preview FILE.svg] [--json] [--compare] [-o FILE.csv|FILE.ngc]
//  [gantry options]`: plans the needle path of a pin marker and times it on the simulated gantry.
#include <cstdio>
#include <iostream>

#include "fonts/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/gantry_options.hpp"
#include "marker/cli/layout_options.hpp"
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
  std::string planner = "optimized";
  std::string window;  // "WxH" in mm; empty: the dots' bounding box
  std::optional<double> pitch_mm;
  std::string preview;
  std::string output;
  bool json = false;
  bool compare = false;
  bool block_straight = false;
};

// "63x38" → 63 × 38 mm.
Box parse_window(const std::string& s) {
  const std::size_t x = s.find_first_of("xX");
  double w = 0, h = 0;
  try {
    std::size_t used_w = 0, used_h = 0;
    if (x == std::string::npos) throw std::invalid_argument("no x");
    w = std::stod(s.substr(0, x), &used_w);
    h = std::stod(s.substr(x + 1), &used_h);
    if (used_w != x || used_h != s.size() - x - 1) throw std::invalid_argument("trailing");
  } catch (const std::exception&) {
    throw InputError("--window '" + s + "': expected WIDTHxHEIGHT in millimetres, e.g. 63x38");
  }
  if (!(w > 0) || !(h > 0))
    throw InputError("--window '" + s + "': width and height must be positive");
  return centred_window(w, h);
}

DotText build_dots(const PeenArgs& a) {
  const std::string text = unescape_text(a.text);
  DotText dots;
  if (const DotFont* font = find_dot_font(a.layout.font)) {
    dots = layout_dot_text(text, *font, to_layout_options(a.layout));
  } else {
    // Any stroke font: "continuous" dots along the strokes.
    const double pitch = a.pitch_mm ? *a.pitch_mm : a.layout.height_mm / 10;
    dots = dots_along_strokes(build_figure(a.text, a.layout).figure, pitch);
  }
  if (dots.dots.empty()) throw InputError("text '" + a.text + "' has no dots to strike");
  if (!(a.layout.field_mm > 0)) throw InputError("--field must be a positive size in mm");
  require_inside(dots.bounds(), Field{a.layout.field_mm}, "the dot text");
  return dots;
}

// printf-style formatting onto std::cout (one stream for everything the command prints).
template <class... T>
void print(const char* format, T... values) {
  char line[256];
  std::snprintf(line, sizeof line, format, values...);
  std::cout << line;
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
  const GantryConfig gantry = to_gantry(a.gantry);
  const DotText dots = build_dots(a);
  const Box window = a.window.empty() ? tight_window(dots) : parse_window(a.window);
  require_inside(window, Field{a.layout.field_mm}, "the marking window");
  const PeenSetup setup{window, gantry, !a.block_straight, &interrupt_flag()};
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

  if (!a.output.empty()) export_plan(a.output, plan, dots, gantry);
  if (!a.preview.empty()) write_peen_preview(dots, plan, window, a.preview);

  if (a.json) {
    nlohmann::json out = result;
    out["window_mm"] = {{"x_min", window.min.x()}, {"y_min", window.min.y()},
                        {"x_max", window.max.x()}, {"y_max", window.max.y()}};
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
  a->layout.font = "5x7";
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand(
            "peen", "plan a pin marker's needle path for the text and time it on the simulated gantry");
        sub->add_option("text", a->text, "text to mark (UTF-8; \\n starts a new line)")->required();
        add_layout_options(*sub, a->layout);
        sub->get_option("--font")->description(
            "dot-matrix font 5x7, 7x9 or 10x16; or a stroke font ('builtin', an installed name, a "
            ".jhf/.lff/.cxf file) marked as dots along its strokes");
        sub->add_option("--planner", a->planner, "needle path planner")
            ->check(CLI::IsMember({"snake", "block", "optimized"}))
            ->capture_default_str();
        sub->add_option("--window", a->window,
                        "marking window WIDTHxHEIGHT in mm, centred on the field (default: the "
                        "dots' bounding box); the whole-window snake sweeps all of it");
        sub->add_option("--pitch", a->pitch_mm,
                        "dot pitch along strokes for stroke fonts, mm (default: height / 10)");
        sub->add_flag("--compare", a->compare, "time all three planners side by side");
        sub->add_flag("--json", a->json, "print the result as JSON");
        sub->add_option("--preview", a->preview, "draw dots and needle path to FILE.svg or FILE.png");
        sub->add_option("-o,--output", a->output,
                        "write the plan as a move/strike list (FILE.csv) or G-code (FILE.ngc)");
        sub->add_flag("--block-straight", a->block_straight,
                      "let the block snake move both axes together (not the patent's track)");
        add_gantry_options(*sub, a->gantry);
        return sub;
      },
      [a] { return run_peen(*a); });
}

}  // namespace mark::cli
