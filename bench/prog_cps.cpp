// Characters per second, SCANLAB's method (galvo.md §5): the 62 characters A–Z a–z 0–9 in the
// built-in font at 1 mm cap height, marked on each simulated head with each corner strategy.
// For two quality levels the fastest marking speed that still meets the level is searched, and
// the characters per second at that speed are reported in device time. Every trial is a
// virtual-time run of the whole job: layout, plan, locus, line memory, drain with the laser
// delay line, simulated scanner, quality figures.
//
//   cps [--short] [--json] [--head NAME] [--strategy NAME]
//   cps --speed MM_S [--head NAME] [--strategy NAME] [--text T] [--font F] [tuning options]
// --speed evaluates one speed and prints its quality figures instead of searching.
#include <CLI/CLI.hpp>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "driver/head_model.hpp"
#include "fonts/catalog.hpp"
#include "fonts/error.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job.hpp"

namespace {

using namespace mark;

constexpr const char* kCharacters = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

struct Level {
  const char* name;
  double max_deviation_um;
  double min_coverage;
  double max_dose_ratio;
};
constexpr Level kHigh{"high", 10, 0.995, 1.3};
constexpr Level kGood{"good", 30, 0.98, 2.0};

// The speed search's range: below it no head is worth marking with, above it the heads'
// tracking lag exceeds the 1 mm letters themselves.
constexpr double kSlowest_mm_s = 40, kFastest_mm_s = 5000;

struct Setup {
  HeadModel head;
  CornerStrategy strategy = CornerStrategy::blanking;
  PenRules rules;
  double join_speed_mm_s = 0;  // 0: the pen's default (jump speed); < 0: marking speed
};

// The text laid out once; its intended strokes indexed once for every trial.
struct Workload {
  std::string text = kCharacters;
  std::shared_ptr<const StrokeFont> font;
  LayoutOptions layout;
  std::unique_ptr<QualityReference> reference;
  double characters = 62;

  Workload(std::string t, const std::string& font_name) : text(std::move(t)) {
    font = open_font(font_name);
    layout.height_mm = 1.0;
    layout.align = Align::center;
    // Baseline 0.5 mm above the field centre, so no mark falls in x < 0 and y < 0 at once: the
    // scanner branch's dose raster crashes in its tile (−1, −1), whose key equals its cache
    // sentinel UINT64_MAX (reported; not ours to change).
    layout.base = Point(0, 0.5);
    reference = std::make_unique<QualityReference>(
        intended_polylines(layout_text(text, *font, layout)));
    characters = 0;
    for (char c : text) characters += c != ' ' && c != '\n';
  }
};

struct Trial {
  double speed_mm_s = 0;
  double mark_time_s = 0;
  Quality quality;
};

Trial mark_at(const Workload& w, const Setup& setup, double speed_mm_s) {
  JobSpec spec;
  spec.text = w.text;
  spec.font = w.font;
  spec.layout = w.layout;
  spec.head = setup.head;
  spec.pen = pen_for_head(setup.head, setup.strategy, speed_mm_s, 10e-6, setup.rules);
  if (setup.join_speed_mm_s < 0) spec.pen.join_speed_mm_s = speed_mm_s;
  if (setup.join_speed_mm_s > 0) spec.pen.join_speed_mm_s = setup.join_speed_mm_s;
  JobOptions options;
  options.virtual_time = true;
  SimScanner scanner(simulator_options(spec));
  const JobResult r = run_job_simulated(spec, options, scanner, w.reference.get());
  return {speed_mm_s, r.mark_time_s, *r.quality};
}

bool meets(const Quality& q, const Level& level) {
  return q.max_deviation_um <= level.max_deviation_um && q.coverage >= level.min_coverage &&
         q.dose_ratio_max <= level.max_dose_ratio;
}

// The fastest speed meeting the level, by bisection of log(speed) between the range's ends:
// `steps` halvings of the ratio 125 leave 1.0 % (9 steps) or 16 % (5, --short) between the
// reported speed and the first failing one. Quality falls with speed but not strictly
// monotonically, so this finds a pass/fail boundary, not necessarily the highest passing speed.
std::optional<Trial> fastest(const Workload& w, const Setup& setup, const Level& level, int steps) {
  Trial lo = mark_at(w, setup, kSlowest_mm_s);
  if (!meets(lo.quality, level)) return std::nullopt;
  const double top = std::min(kFastest_mm_s, setup.head.max_speed_mm_s);
  Trial hi_trial = mark_at(w, setup, top);
  if (meets(hi_trial.quality, level)) return hi_trial;
  double hi = top;
  for (int i = 0; i < steps; ++i) {
    const double mid = std::sqrt(lo.speed_mm_s * hi);
    Trial t = mark_at(w, setup, mid);
    if (meets(t.quality, level)) lo = t;
    else hi = mid;
  }
  return lo;
}

struct Row {
  std::string head, strategy, level;
  std::optional<Trial> trial;
  double cps = 0;
};

void print_row(const Row& r) {
  if (!r.trial) {
    std::printf("%-6s %-9s %-5s %10s %8s   not reached at %.0f mm/s\n", r.head.c_str(),
                r.strategy.c_str(), r.level.c_str(), "-", "-", kSlowest_mm_s);
    return;
  }
  const Quality& q = r.trial->quality;
  std::printf("%-6s %-9s %-5s %10.0f %8.0f   %5.1f / %4.1f / %.4f / %.2f\n", r.head.c_str(),
              r.strategy.c_str(), r.level.c_str(), r.trial->speed_mm_s, r.cps, q.max_deviation_um,
              q.rms_deviation_um, q.coverage, q.dose_ratio_max);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"characters per second on the simulated heads (SCANLAB's cps method)"};
  bool quick = false, json = false;
  std::string head_name, strategy_name, text = kCharacters, font = kBuiltinFontName;
  double speed = 0, join_speed = 0;
  unsigned workers = 2;
  PenRules rules;
  app.add_flag("--short", quick, "coarser speed search (for CI)");
  app.add_flag("--json", json, "print rows {head, strategy, quality, speed_mm_s, cps} as JSON");
  app.add_option("--head", head_name, "only this head (SL10, SL14, cheap)");
  app.add_option("--strategy", strategy_name, "only this corner strategy (blanking, delays, none)");
  app.add_option("--workers", workers, "searches run in parallel (each a producer and a drain thread)");
  app.add_option("--speed", speed, "evaluate this marking speed only (mm/s)");
  app.add_option("--text", text, "mark this text instead (diagnosis)");
  app.add_option("--font", font, "in this font instead (diagnosis)");
  app.add_option("--join-speed", join_speed, "blanking join speed, mm/s (-1: marking speed)");
  app.add_option("--run-in", rules.run_in, "fixed blanking run-in length, multiple of v·τ");
  app.add_option("--min-run-in", rules.min_run_in, "shortest automatic run-in, multiple of v·τ");
  app.add_option("--run-out", rules.run_out, "blanking run-out length, multiple of v·τ");
  app.add_option("--settle", rules.settle_um, "transient left at laser on, µm");
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
    const Workload work(text, font);

    if (speed > 0) {
      for (const HeadModel& h : heads)
        for (CornerStrategy s : strategies) {
          const Trial t = mark_at(work, {h, s, rules, join_speed}, speed);
          std::printf("%-6s %-9s %7.0f mm/s  max %6.1f µm  rms %5.1f µm  cov %.4f  dose %.3f  "
                      "over %5.1f µm  %.4f s  %6.0f cps\n",
                      h.name.c_str(), std::string(to_string(s)).c_str(), speed,
                      t.quality.max_deviation_um, t.quality.rms_deviation_um, t.quality.coverage,
                      t.quality.dose_ratio_max, t.quality.overshoot_um, t.mark_time_s,
                      work.characters / t.mark_time_s);
        }
      return 0;
    }

    // Every (head, strategy, level) is an independent search; run them on `workers` threads
    // and print in table order.
    std::vector<Row> rows;
    std::vector<Setup> setups;
    std::vector<const Level*> levels;
    for (const HeadModel& h : heads)
      for (CornerStrategy s : strategies)
        for (const Level* level : {&kHigh, &kGood}) {
          rows.push_back({h.name, std::string(to_string(s)), level->name, std::nullopt, 0});
          setups.push_back({h, s, rules, join_speed});
          levels.push_back(level);
        }
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto worker = [&] {
      for (std::size_t i; (i = next++) < rows.size();) {
        try {
          rows[i].trial = fastest(work, setups[i], *levels[i], quick ? 5 : 9);
          if (rows[i].trial) rows[i].cps = work.characters / rows[i].trial->mark_time_s;
        } catch (...) {
          std::lock_guard<std::mutex> lock(error_mutex);
          error = std::current_exception();
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned i = 0; i < std::max(1u, workers); ++i) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);

    if (json) {
      nlohmann::json out = nlohmann::json::array();
      for (const Row& r : rows)
        out.push_back({{"head", r.head}, {"strategy", r.strategy}, {"quality", r.level},
                       {"speed_mm_s", r.trial ? r.trial->speed_mm_s : 0.0}, {"cps", r.cps}});
      std::cout << out.dump() << "\n";
      return 0;
    }
    std::printf("cps: 62 characters A–Z a–z 0–9, built-in font, 1 mm cap height, device time%s\n",
                quick ? " (short search: speeds within 16 %)" : " (speeds within 1 %)");
    std::printf("%-6s %-9s %-5s %10s %8s   %s\n", "head", "strategy", "level", "speed mm/s",
                "cps", "max µm / rms µm / coverage / dose ratio at that speed");
    for (const Row& r : rows) print_row(r);
  } catch (const std::exception& e) {
    std::cerr << "cps: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
