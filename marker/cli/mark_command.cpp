// `marker mark TEXT [layout options] [--device sim] [--head SL10|SL14|cheap]
//  [--corner blanking|delays|none] [--speed MM_S] [--preview FILE.png] [--virtual-time] [--json]`
// The main job on the simulated scanner: real time by default (the drain paced at the tick, so the
// line memory is written while it is read), quality figures against the laid-out text.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "driver/dose_png.hpp"
#include "fonts/catalog.hpp"
#include "fonts/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/preview/mark_preview.hpp"

namespace mark::cli {
namespace {

struct MarkArgs {
  std::string text;
  LayoutArgs layout;
  std::string device = "sim";
  std::string head = "SL10";
  std::string corner = "blanking";
  std::string order = "glyph";
  double speed_mm_s = 1000;
  double jump_speed_mm_s = 0;  // 0: the head's default
  double tick_us = 10;
  std::optional<double> run_in_mm;
  std::optional<double> run_out_mm;
  std::string preview;
  std::string dose_png;
  bool virtual_time = false;
  bool json = false;
};

JobSpec make_spec(const MarkArgs& a) {
  if (a.device != "sim")
    throw InputError("--device '" + a.device + "': only 'sim' (the simulated scanner) is available");
  JobSpec spec;
  const auto head = find_head(a.head);
  if (!head) throw InputError("--head '" + a.head + "' is not one of SL10, SL14, cheap");
  spec.head = *head;
  if (!(a.layout.field_mm > 0)) throw InputError("--field must be a positive size in mm");
  spec.head.field_mm = a.layout.field_mm;
  Warnings warnings;
  spec.font = open_font(a.layout.font, &warnings);
  for (const std::string& w : warnings) std::cerr << "marker: warning: " << w << "\n";
  spec.text = unescape_text(a.text);
  spec.layout = to_layout_options(a.layout);
  spec.order = parse_stroke_order(a.order);
  spec.pen = pen_for_head(spec.head, parse_corner_strategy(a.corner), a.speed_mm_s,
                          a.tick_us * 1e-6);
  if (a.jump_speed_mm_s != 0) {
    spec.pen.jump_speed_mm_s = a.jump_speed_mm_s;
    if (spec.pen.corner == CornerStrategy::blanking) spec.pen.join_speed_mm_s = a.jump_speed_mm_s;
  }
  if (a.run_in_mm) spec.pen.run_in_mm = *a.run_in_mm;
  if (a.run_out_mm) spec.pen.run_out_mm = *a.run_out_mm;
  return spec;
}

nlohmann::json to_json(const JobSpec& spec, const JobResult& r) {
  nlohmann::json j = {{"glyphs", r.glyphs},
                      {"strokes", r.strokes},
                      {"commands", r.commands},
                      {"samples", r.samples},
                      {"mark_time_s", r.mark_time_s},
                      {"compile_time_s", r.compile_time_s},
                      {"wall_time_s", r.wall_time_s},
                      {"underruns", r.drain.underrun_events},
                      {"underrun_samples", r.drain.underrun_samples},
                      {"jump_length_mm", r.jump_length_mm},
                      {"head", spec.head.name},
                      {"corner", to_string(spec.pen.corner)},
                      {"speed_mm_s", spec.pen.mark_speed_mm_s},
                      {"tick_s", spec.pen.tick_s},
                      {"peak_fill", r.drain.peak_fill},
                      {"lateness_p99_us", r.drain.lateness_p99_us}};
  if (r.quality)
    j["quality"] = {{"max_deviation_um", r.quality->max_deviation_um},
                    {"rms_deviation_um", r.quality->rms_deviation_um},
                    {"coverage", r.quality->coverage},
                    {"dose_ratio_max", r.quality->dose_ratio_max},
                    {"overshoot_um", r.quality->overshoot_um}};
  return j;
}

void print_summary(const JobSpec& spec, const JobResult& r) {
  std::printf("marked %zu glyphs (%zu strokes, %zu commands) on %s, %s corners, %.0f mm/s\n",
              r.glyphs, r.strokes, r.commands, spec.head.name.c_str(),
              std::string(to_string(spec.pen.corner)).c_str(), spec.pen.mark_speed_mm_s);
  std::printf("mark time %.4f s (device), %llu samples, compile %.1f µs, jumps %.1f mm, "
              "underruns %llu\n",
              r.mark_time_s, static_cast<unsigned long long>(r.samples), r.compile_time_s * 1e6,
              r.jump_length_mm, static_cast<unsigned long long>(r.drain.underrun_events));
  if (r.quality)
    std::printf("quality: max deviation %.1f µm, rms %.1f µm, coverage %.2f %%, dose ratio %.2f, "
                "overshoot %.1f µm\n",
                r.quality->max_deviation_um, r.quality->rms_deviation_um,
                100 * r.quality->coverage, r.quality->dose_ratio_max, r.quality->overshoot_um);
}

// Progress on stderr for a job that takes longer than about a second; cleared at the end.
std::function<void(std::uint64_t, std::uint64_t)> progress_printer() {
  const auto t0 = std::chrono::steady_clock::now();
  auto shown = std::make_shared<bool>(false);
  return [t0, shown](std::uint64_t done, std::uint64_t total) {
    if (total == 0) return;
    if (done >= total) {
      if (*shown) std::fprintf(stderr, "\r%40s\r", "");
      return;
    }
    if (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(1)) return;
    *shown = true;
    std::fprintf(stderr, "\rmarking %3.0f %%", 100.0 * static_cast<double>(done) / total);
  };
}

}  // namespace

Command make_mark_command() {
  auto a = std::make_shared<MarkArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("mark", "mark the text on the simulated scanner");
        sub->add_option("text", a->text, "text to mark (UTF-8; \\n starts a new line)")->required();
        add_layout_options(*sub, a->layout);
        sub->add_option("--device", a->device, "device: sim (the simulated scanner)")->capture_default_str();
        sub->add_option("--head", a->head, "scan head preset: SL10, SL14, cheap")->capture_default_str();
        sub->add_option("--corner", a->corner, "corner strategy: blanking, delays, none")->capture_default_str();
        sub->add_option("--order", a->order, "stroke order: glyph, shortest (least jumping)")->capture_default_str();
        sub->add_option("--speed", a->speed_mm_s, "marking speed, mm/s")->capture_default_str();
        sub->add_option("--jump-speed", a->jump_speed_mm_s,
                        "jump speed, mm/s (default: half the head's positioning limit)");
        sub->add_option("--tick", a->tick_us, "locus tick, µs")->capture_default_str();
        sub->add_option("--run-in", a->run_in_mm,
                        "blanking run-in length, mm (default: sized by the head's settling)");
        sub->add_option("--run-out", a->run_out_mm, "blanking run-out length, mm (default v·τ)");
        sub->add_option("--preview", a->preview,
                        "write the marked result: dose under the planned path (.png or .svg)");
        sub->add_option("--dose-png", a->dose_png, "write the raw dose raster as a PNG");
        sub->add_flag("--virtual-time", a->virtual_time,
                      "drain as fast as the device accepts (device time is still reported)");
        sub->add_flag("--json", a->json, "print one JSON object with the job's figures");
        return sub;
      },
      [a] {
        const JobSpec spec = make_spec(*a);
        JobOptions options;
        options.virtual_time = a->virtual_time;
        if (!a->json && isatty(STDERR_FILENO)) options.progress = progress_printer();
        SimScanner scanner(simulator_options(spec));
        const JobResult r = run_job_simulated(spec, options, scanner);
        if (!a->preview.empty()) write_mark_preview(r.job.plan, scanner.dose(), a->preview);
        if (!a->dose_png.empty()) write_dose_png(scanner.dose(), a->dose_png);
        if (a->json) {
          std::cout << to_json(spec, r).dump() << "\n";
        } else {
          print_summary(spec, r);
          if (!a->preview.empty()) std::printf("wrote %s\n", a->preview.c_str());
        }
        return 0;
      });
}

}  // namespace mark::cli
