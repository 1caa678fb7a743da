// Characters per second, SCANLAB's method (galvo.md §5): the 62 characters A–Z a–z 0–9 in the
// built-in font at 1 mm cap height, marked on each simulated head with each corner strategy.
// For two quality levels the fastest marking speed that still meets the level is searched, and
// the characters per second at that speed are reported in device time (virtual-time runs of the
// whole job: layout, plan, locus, line memory, drain with laser delay line, simulated scanner).
//
//   cps [--short] [--json] [--head NAME] [--strategy NAME] [--speed MM_S] [--run-in K]
//       [--run-out K]
// --speed evaluates one speed and prints its quality figures instead of searching.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driver/head_model.hpp"
#include "fonts/catalog.hpp"
#include "fonts/error.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"

namespace {

using namespace mark;

constexpr const char* kCharacters = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
constexpr double kCharacterCount = 62;

struct Level {
  const char* name;
  double max_deviation_um;
  double min_coverage;
  double max_dose_ratio;
};
constexpr Level kHigh{"high", 10, 0.995, 1.3};
constexpr Level kGood{"good", 30, 0.98, 2.0};

struct Trial {
  double speed_mm_s = 0;
  double mark_time_s = 0;
  Quality quality;
};

struct Setup {
  HeadModel head;
  CornerStrategy strategy;
  PenRules rules;
  std::string text = kCharacters;
  double join_speed_mm_s = 0;  // 0: the pen's default (jump speed)
  std::string font = kBuiltinFontName;
};

Trial mark_at(const Setup& setup, double speed_mm_s) {
  JobSpec spec;
  spec.text = setup.text;
  spec.font = open_font(setup.font);
  spec.layout.height_mm = 1.0;
  spec.layout.align = Align::center;
  // Baseline 0.5 mm above the field centre, so no mark falls in x < 0 and y < 0 at the same
  // time (the dose raster of the scanner branch crashes in its tile (−1, −1): its cache sentinel
  // UINT64_MAX equals that tile's key; reported, not ours to fix).
  spec.layout.base = Point(0, 0.5);
  spec.head = setup.head;
  spec.pen = pen_for_head(setup.head, setup.strategy, speed_mm_s, 10e-6, setup.rules);
  if (setup.join_speed_mm_s < 0) spec.pen.join_speed_mm_s = speed_mm_s;  // join at marking speed
  else if (setup.join_speed_mm_s > 0) spec.pen.join_speed_mm_s = setup.join_speed_mm_s;
  JobOptions options;
  options.virtual_time = true;
  SimScanner scanner(simulator_options(spec));
  const JobResult r = run_job_simulated(spec, options, scanner);
  return {speed_mm_s, r.mark_time_s, *r.quality};
}

bool meets(const Quality& q, const Level& level) {
  return q.max_deviation_um <= level.max_deviation_um && q.coverage >= level.min_coverage &&
         q.dose_ratio_max <= level.max_dose_ratio;
}

// The fastest speed meeting the level: a geometric scan upward from a slow speed until the level
// fails (the figures are not strictly monotone in speed, so the scan goes on one step past a
// failure), then bisection between the best pass and the next failure.
std::optional<Trial> fastest(const Setup& setup, const Level& level, bool quick) {
  const double factor = quick ? 1.6 : 1.25;
  const int bisections = quick ? 3 : 6;
  std::optional<Trial> best;
  double fail_above = 0;
  int misses = 0;
  for (double v = 20; v <= setup.head.max_speed_mm_s * 0.5; v *= factor) {
    Trial t = mark_at(setup, v);
    if (meets(t.quality, level)) {
      best = t, misses = 0, fail_above = 0;
    } else if (best || v > 200) {
      if (!fail_above) fail_above = v;
      if (++misses >= 2) break;
    }
  }
  if (!best) return best;
  double lo = best->speed_mm_s, hi = fail_above ? fail_above : lo * factor;
  for (int i = 0; i < bisections; ++i) {
    const double mid = std::sqrt(lo * hi);
    Trial t = mark_at(setup, mid);
    if (meets(t.quality, level)) best = t, lo = mid;
    else hi = mid;
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"characters per second on the simulated heads (SCANLAB's cps method)"};
  bool quick = false, json = false;
  std::string head_name, strategy_name;
  double speed = 0;
  PenRules rules;
  std::string text = kCharacters;
  double join_speed = 0;
  std::string font = kBuiltinFontName;
  app.add_option("--font", font, "with --speed: mark in this font instead (diagnosis)");
  app.add_option("--join-speed", join_speed, "with --speed: blanking join speed, mm/s (-1: marking speed)");
  app.add_flag("--short", quick, "coarser speed search (for CI)");
  app.add_flag("--json", json, "print rows {head, strategy, quality, speed_mm_s, cps} as JSON");
  app.add_option("--head", head_name, "only this head (SL10, SL14, cheap)");
  app.add_option("--strategy", strategy_name, "only this corner strategy (blanking, delays, none)");
  app.add_option("--speed", speed, "evaluate this marking speed only (mm/s)");
  app.add_option("--text", text, "with --speed: mark this text instead (diagnosis)");
  app.add_option("--run-in", rules.run_in, "fixed blanking run-in length, multiple of v·τ");
  app.add_option("--min-run-in", rules.min_run_in, "shortest automatic run-in, multiple of v·τ");
  app.add_option("--settle", rules.settle_um, "transient left at laser on, µm (automatic run-in)");
  app.add_option("--run-out", rules.run_out, "blanking run-out length, multiple of v·τ");
  app.add_option("--blank-angle", rules.blank_angle_deg, "blanking threshold, degrees");
  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<HeadModel> heads;
    if (head_name.empty()) {
      for (const std::string& n : head_names()) heads.push_back(*find_head(n));
    } else if (const auto h = find_head(head_name)) {
      heads.push_back(*h);
    } else {
      throw InputError("unknown head '" + head_name + "'");
    }
    std::vector<CornerStrategy> strategies = {CornerStrategy::blanking, CornerStrategy::delays,
                                              CornerStrategy::none};
    if (!strategy_name.empty()) strategies = {parse_corner_strategy(strategy_name)};

    if (speed > 0) {
      for (const HeadModel& h : heads)
        for (CornerStrategy s : strategies) {
          const Trial t = mark_at({h, s, rules, text, join_speed, font}, speed);
          std::printf("%-6s %-9s %7.0f mm/s  max %6.1f µm  rms %5.1f µm  cov %.4f  dose %.3f  "
                      "over %5.1f µm  %.4f s  %6.0f cps\n",
                      h.name.c_str(), std::string(to_string(s)).c_str(), speed,
                      t.quality.max_deviation_um, t.quality.rms_deviation_um, t.quality.coverage,
                      t.quality.dose_ratio_max, t.quality.overshoot_um, t.mark_time_s,
                      kCharacterCount / t.mark_time_s);
        }
      return 0;
    }

    nlohmann::json rows = nlohmann::json::array();
    if (!json)
      std::printf("%-6s %-9s %-5s %10s %8s   %s\n", "head", "strategy", "level", "speed mm/s",
                  "cps", "max µm / rms µm / coverage / dose ratio");
    for (const HeadModel& h : heads)
      for (CornerStrategy s : strategies)
        for (const Level& level : {kHigh, kGood}) {
          const std::optional<Trial> t = fastest({h, s, rules}, level, quick);
          const double cps = t ? kCharacterCount / t->mark_time_s : 0;
          rows.push_back({{"head", h.name}, {"strategy", to_string(s)}, {"quality", level.name},
                          {"speed_mm_s", t ? t->speed_mm_s : 0.0}, {"cps", cps}});
          if (json) continue;
          if (!t) {
            std::printf("%-6s %-9s %-5s %10s %8s   not reached at any speed searched\n",
                        h.name.c_str(), std::string(to_string(s)).c_str(), level.name, "-", "-");
          } else {
            std::printf("%-6s %-9s %-5s %10.0f %8.0f   %.1f / %.1f / %.4f / %.2f\n",
                        h.name.c_str(), std::string(to_string(s)).c_str(), level.name,
                        t->speed_mm_s, cps, t->quality.max_deviation_um,
                        t->quality.rms_deviation_um, t->quality.coverage,
                        t->quality.dose_ratio_max);
          }
          std::fflush(stdout);
        }
    if (json) std::cout << rows.dump() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "cps: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
