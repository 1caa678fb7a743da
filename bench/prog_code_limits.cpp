// The limits of a code mark on the simulated scanner, read back by the real decoders:
//  - the smallest module that still decodes, per module style, on a head at the default pen
//    (1000 mm/s, blanking) — a 16 × 16 Data Matrix;
//  - the fastest marking speed at which an 8 mm 16 × 16 Data Matrix (0.5 mm modules, hatched)
//    still decodes, per head, and the mark time against speed (the Omron anchor, dynamics.md
//    §5.4: doubling the speed to 1 m/s took 54 % of the time).
// A setting counts as decoding when the decoded data equals the data; a stricter "solid" count
// also wants every module on the right side of half marked (no module that only the reader's
// error correction saves). The module scans also give the smallest module still at ISO/IEC
// TR 29158 grade C or better off the camera model's picture, and the grade at the smallest
// module that decodes. The scans go from the easy end; "reliable" is the end of the first
// unbroken run of passing settings, "extreme" the most extreme setting that passed at all.
//
//   code_limits [--head SL10] [--corner blanking] [--json] [--step-um 2.5] [--speed-step 250]
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "marker/job/head_pen.hpp"
#include "marker/job/simulate_plan.hpp"

namespace {

using namespace mark;

const char* kData = "SN 2026-000123";  // 14 characters: a 16 × 16 symbol

struct Trial {
  double value = 0;
  bool reads = false;
  bool solid = false;
  double mark_time_s = 0;
  double fill_ratio = 0;
  int grade = 0;  // ISO/IEC TR 29158 overall grade off the camera's picture: 4 A … 1 D, 0 F or none
};

constexpr int kGradeC = 2;

CornerStrategy corner = CornerStrategy::blanking;

Trial trial(const HeadModel& head, ModuleStyle style, double module_mm, double speed_mm_s) {
  CodeObject code;
  code.spec.data = kData;
  code.spec.matrix_rows = code.spec.matrix_cols = 16;
  code.layout.module_mm = module_mm;
  code.layout.style = style;
  JobSpec job;
  job.codes.push_back(code);
  job.head = head;
  job.pen = pen_for_head(head, corner, speed_mm_s);
  try {
    const SimulatedJob r = simulate_job(job);
    const CodeVerification& v = r.codes.front();
    return {0, v.data_match, v.data_match && v.modules_wrong == 0, r.mark.mark_time_s, v.fill_ratio.value_or(0),
            v.grade ? v.grade->overall : 0};
  } catch (const std::exception&) {
    return {};  // a layout the style refuses (modules narrower than the beam) does not read
  }
}

struct Limit {
  std::optional<double> reliable;  // end of the first unbroken run of passing values
  std::optional<double> extreme;   // most extreme passing value of the scan
};

// Scans from `from` to `to`; `test` returns whether a value passes.
template <class F>
Limit scan(double from, double to, double step, F&& test) {
  Limit l;
  bool run_over = false;
  const int n = static_cast<int>(std::floor(std::abs(to - from) / step + 1e-9));
  for (int k = 0; k <= n; ++k) {
    const double v = from + (to > from ? 1 : -1) * k * step;
    if (test(v)) {
      l.extreme = v;
      if (!run_over) l.reliable = v;
    } else if (l.reliable) {
      run_over = true;
    }
  }
  return l;
}

std::string text(const std::optional<double>& v, const char* format) {
  if (!v) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, format, *v);
  return buf;
}

nlohmann::json to_json(const Limit& l) {
  return {{"reliable", l.reliable ? nlohmann::json(*l.reliable) : nlohmann::json(nullptr)},
          {"extreme", l.extreme ? nlohmann::json(*l.extreme) : nlohmann::json(nullptr)}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"smallest decodable module and fastest decodable speed of a Data Matrix on the simulated scanner"};
  std::string head_name = "SL10", corner_name = "blanking";
  bool json = false;
  double step_um = 2.5, speed_step = 250;
  app.add_option("--head", head_name, "head preset")->capture_default_str();
  app.add_option("--corner", corner_name, "corner strategy")->capture_default_str();
  app.add_option("--step-um", step_um, "module scan step, µm")->capture_default_str();
  app.add_option("--speed-step", speed_step, "speed scan step, mm/s")->capture_default_str();
  app.add_flag("--json", json, "print JSON");
  CLI11_PARSE(app, argc, argv);
  const auto head = find_head(head_name);
  if (!head) {
    std::cerr << "code_limits: unknown head " << head_name << "\n";
    return 1;
  }
  corner = parse_corner_strategy(corner_name);
  nlohmann::json out = {{"head", head->name}, {"corner", corner_name}, {"data", kData}, {"symbol", "datamatrix 16x16"}};

  // Smallest module, scanning down; at the default pen (1000 mm/s) and, for dots, also at the
  // slow speed dots need.
  const struct {
    ModuleStyle style;
    double speed_mm_s, from_mm, to_mm;
  } styles[] = {{ModuleStyle::square, 1000, 0.20, 0.04},
                {ModuleStyle::line, 1000, 0.20, 0.02},
                {ModuleStyle::dot, 1000, 0.40, 0.05},
                {ModuleStyle::dot, 150, 0.40, 0.05}};
  for (const auto& s : styles) {
    const std::string key = std::string(to_string(s.style)) + "_" + std::to_string(static_cast<int>(s.speed_mm_s)) + "_mm_s";
    // One mark per module; the decode and the grade C scans read the same marks.
    std::map<double, Trial> marked;
    const auto at = [&](double m) -> const Trial& {
      auto it = marked.find(m);
      if (it == marked.end()) it = marked.emplace(m, trial(*head, s.style, m, s.speed_mm_s)).first;
      return it->second;
    };
    const Limit l = scan(s.from_mm, s.to_mm, step_um / 1000, [&](double m) { return at(m).reads; });
    const Limit c = scan(s.from_mm, s.to_mm, step_um / 1000, [&](double m) { return at(m).grade >= kGradeC; });
    out["smallest_module_mm"][key] = to_json(l);
    out["smallest_module_grade_c_mm"][key] = to_json(c);
    const int grade_at_smallest = l.reliable ? at(*l.reliable).grade : 0;
    out["grade_at_smallest_module"][key] = grade_at_smallest;
    if (!json)
      std::printf("%s %-6s at %4.0f mm/s: smallest module that decodes %s mm (reliable, grade %c), %s mm (any); "
                  "at grade C or better %s mm (reliable)\n",
                  head->name.c_str(), std::string(to_string(s.style)).c_str(), s.speed_mm_s,
                  text(l.reliable, "%.4f").c_str(), "FDCBA"[std::clamp(grade_at_smallest, 0, 4)],
                  text(l.extreme, "%.4f").c_str(), text(c.reliable, "%.4f").c_str());
  }

  // Fastest speed for the 8 mm symbol, and time against speed.
  const double top = std::min(head->max_speed_mm_s, 10000.0);
  nlohmann::json times = nlohmann::json::array();
  std::vector<Trial> trials;
  const Limit fastest = scan(500, top, speed_step, [&](double v) {
    Trial t = trial(*head, ModuleStyle::square, 0.5, v);
    t.value = v;
    trials.push_back(t);
    times.push_back({{"speed_mm_s", v}, {"reads", t.reads}, {"solid", t.solid}, {"mark_time_s", t.mark_time_s},
                     {"fill_ratio", t.fill_ratio}});
    return t.reads;
  });
  std::size_t next = 0;
  const Limit fastest_solid = scan(500, top, speed_step, [&](double) { return trials[next++].solid; });
  out["fastest_speed_mm_s_8mm"] = to_json(fastest);
  out["fastest_solid_speed_mm_s_8mm"] = to_json(fastest_solid);
  out["trials_8mm"] = times;
  const double t500 = trial(*head, ModuleStyle::square, 0.5, 500).mark_time_s;
  const double t1000 = trial(*head, ModuleStyle::square, 0.5, 1000).mark_time_s;
  out["time_ratio_1000_vs_500"] = t1000 / t500;
  if (json) {
    std::cout << out.dump(1) << "\n";
  } else {
    std::printf("%s 8 mm 16x16: fastest decoding speed %s mm/s (reliable), %s mm/s (any); every module right up to %s mm/s\n",
                head->name.c_str(), text(fastest.reliable, "%.0f").c_str(), text(fastest.extreme, "%.0f").c_str(),
                text(fastest_solid.reliable, "%.0f").c_str());
    std::printf("%s 8 mm 16x16: %.3f s at 500 mm/s, %.3f s at 1000 mm/s: %.0f %% of the time (Omron: 54 %%)\n",
                head->name.c_str(), t500, t1000, 100 * t1000 / t500);
    for (const auto& t : times)
      std::printf("  %6.0f mm/s  %-5s %-5s  %.3f s  fill %.2f\n", t["speed_mm_s"].get<double>(),
                  t["reads"].get<bool>() ? "reads" : "FAILS", t["solid"].get<bool>() ? "solid" : "", t["mark_time_s"].get<double>(),
                  t["fill_ratio"].get<double>());
  }
  return 0;
}
