// `marker mark TEXT [layout options] [--device sim] [--head SL10|SL14|cheap|SA14]
//  [--head-model first|second] [--laser-rise-us US] [--corner blanking|delays|none]
//  [--speed MM_S|auto] [--lookahead] [--feed-forward] [--head-profile FILE] [pen parameters]
//  [--preview FILE.png] [--virtual-time] [--json] [--inject KIND@N] [--trace FILE.csv]
//  [--require-quality high|good]`
// The main job: real time by default (the drain paced at the tick, so the line memory is written
// while it is read), quality figures against the laid-out text. Ctrl-C / SIGTERM put the laser
// out within one drain block; the command then says where it stopped and exits 130.
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "driver/dose_png.hpp"
#include "driver/quality_class.hpp"
#include "fonts/catalog.hpp"
#include "fonts/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/device_factory.hpp"
#include "marker/cli/head_options.hpp"
#include "marker/cli/inject_option.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/cli/output_file.hpp"
#include "marker/cli/pen_options.hpp"
#include "marker/job/auto_speed.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/preview/mark_preview.hpp"

namespace mark::cli {
namespace {

struct MarkArgs {
  std::string text;
  LayoutArgs layout;
  std::string device = "sim";
  HeadArgs head;
  PenArgs pen;
  std::string order = "glyph";
  std::string speed = "auto";  // mm/s, or auto: from the figure's tightest curve and the head
  std::string preview;
  std::string dose_png;
  std::string trace;
  std::string inject;
  std::string require_quality;
  bool virtual_time = false;
  bool json = false;
};

JobSpec make_spec(const MarkArgs& a) {
  JobSpec spec;
  spec.head = simulated_head(a.head);
  if (!(a.layout.field_mm > 0)) throw InputError("--field must be a positive size in mm");
  spec.head.field_mm = a.layout.field_mm;
  Warnings warnings;
  spec.font = open_font(a.layout.font, &warnings);
  for (const std::string& w : warnings) std::cerr << "marker: warning: " << w << "\n";
  spec.text = unescape_text(a.text);
  spec.layout = to_layout_options(a.layout);
  spec.order = parse_stroke_order(a.order);
  double speed_mm_s = 0;
  if (a.speed == "auto") {
    speed_mm_s = auto_mark_speed_mm_s(layout_text(spec.text, *spec.font, spec.layout), spec.head);
  } else {
    std::size_t used = 0;
    try {
      speed_mm_s = std::stod(a.speed, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != a.speed.size() || !(speed_mm_s > 0) || !(speed_mm_s <= spec.head.max_speed_mm_s))
      throw InputError("--speed '" + a.speed + "' must be auto or a speed above 0 and at most " +
                       std::to_string(static_cast<int>(spec.head.max_speed_mm_s)) +
                       " mm/s (head " + spec.head.name + ")");
  }
  PenArgs pen = a.pen;
  pen.speed_mm_s = speed_mm_s;
  spec.pen = make_pen(pen, spec.head);
  return spec;
}

nlohmann::json quality_json(const Quality& q) {
  return {{"max_deviation_um", q.max_deviation_um},
          {"rms_deviation_um", q.rms_deviation_um},
          {"coverage", q.coverage},
          {"dose_ratio_max", q.dose_ratio_max},
          {"overshoot_um", q.overshoot_um},
          {"class", to_string(classify(q))}};
}

nlohmann::json to_json(const MarkArgs& a, const JobSpec& spec, const JobResult& r,
                       const std::string& device_name) {
  nlohmann::json j = {{"text", spec.text},
                      {"font", a.layout.font},
                      {"height_mm", spec.layout.height_mm},
                      {"head", spec.head.name},
                      {"head_model", spec.head.second_order ? "second" : "first"},
                      {"laser_rise_us", a.head.laser_rise_us},
                      {"lookahead", spec.pen.lookahead || spec.pen.feed_forward()},
                      {"feed_forward", spec.pen.feed_forward()},
                      {"device", device_name},
                      {"outcome", to_string(r.outcome)},
                      {"ink_marked", r.ink_marked},
                      {"glyphs", r.glyphs},
                      {"strokes", r.strokes},
                      {"commands", r.commands},
                      {"samples", r.samples},
                      {"mark_time_s", r.mark_time_s},
                      {"compile_time_s", r.compile_time_s},
                      {"wall_time_s", r.wall_time_s},
                      {"underruns", r.drain.underrun_events},
                      {"underrun_samples", r.drain.underrun_samples},
                      {"jump_length_mm", r.jump_length_mm},
                      {"corner", to_string(spec.pen.corner)},
                      {"speed_mm_s", spec.pen.mark_speed_mm_s},
                      {"tick_s", spec.pen.tick_s},
                      {"peak_fill_samples", r.drain.peak_fill},
                      {"lateness_p99_us", r.drain.lateness_p99_us},
                      {"lateness_max_us", r.drain.lateness_max_us},
                      {"realtime", {{"sched_fifo", r.drain.realtime_granted},
                                    {"memory_locked", r.memory_locked}}}};
  if (r.outcome != JobOutcome::done) j["stopped_at"] = r.stopped_at;
  if (r.fault)
    j["fault"] = {{"category", to_string(r.fault->category)},
                  {"message", r.fault->message},
                  {"at", r.fault->at}};
  if (r.stop_latency_us >= 0) {
    j["stop_latency_us"] = r.stop_latency_us;
    j["stop_latency_samples"] = r.stop_latency_samples;
  }
  nlohmann::json figures = nlohmann::json::object();
  for (const auto& [name, value] : r.device.figures) figures[name] = value;
  j["device_figures"] = figures;
  if (r.quality) j["quality"] = quality_json(*r.quality);
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
    std::printf("quality: %s — max deviation %.1f µm, rms %.1f µm, coverage %.2f %%, dose ratio "
                "%.2f, overshoot %.1f µm\n",
                std::string(to_string(classify(*r.quality))).c_str(), r.quality->max_deviation_um,
                r.quality->rms_deviation_um, 100 * r.quality->coverage, r.quality->dose_ratio_max,
                r.quality->overshoot_um);
}

// Where a job that did not finish stopped, on one line (stderr).
void print_stop(const JobResult& r, const JobSpec& spec, bool interrupted) {
  const double t = static_cast<double>(r.stopped_at) * spec.pen.tick_s;
  std::string why = r.outcome == JobOutcome::aborted
                        ? (interrupted ? "interrupted" : "aborted")
                        : "failed (" + std::string(to_string(r.fault->category)) + ": " +
                              r.fault->message + ")";
  std::fprintf(stderr,
               "marker: mark %s at sample %llu (%.4f s device time): %.1f %% of the ink marked, "
               "laser off\n",
               why.c_str(), static_cast<unsigned long long>(r.stopped_at), t, 100 * r.ink_marked);
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

void write_trace(const std::vector<SimTraceRow>& rows, const std::string& path) {
  write_file_whole(path, [&](const std::string& tmp) {
    std::FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f) throw InputError("--trace " + path + ": cannot write: " + std::strerror(errno));
    std::fputs("t_s,cmd_x_mm,cmd_y_mm,laser,beam_x_mm,beam_y_mm\n", f);
    for (const SimTraceRow& r : rows)
      std::fprintf(f, "%.6f,%.5f,%.5f,%d,%.5f,%.5f\n", r.t_s, r.cmd_x_mm, r.cmd_y_mm,
                   r.laser ? 1 : 0, r.beam_x_mm, r.beam_y_mm);
    const bool ok = std::ferror(f) == 0;
    if (std::fclose(f) != 0 || !ok)
      throw InputError("--trace " + path + ": cannot write: " + std::strerror(errno));
  });
}

// --require-quality: the simulator predicts the mark (virtual time, no device touched); below
// the class the job is refused before anything fires.
void require_quality(const JobSpec& spec, const std::string& name, double laser_rise_s) {
  const auto wanted = parse_quality_class(name);
  if (!wanted || *wanted == QualityClass::poor)
    throw InputError("--require-quality '" + name + "' is not one of high, good");
  JobOptions predict;
  predict.virtual_time = true;
  SimScannerOptions o = simulator_options(spec);
  o.laser_rise_s = laser_rise_s;
  SimScanner sim(o);
  const JobResult r = run_job_simulated(spec, predict, sim);
  const QualityClass got = classify(*r.quality);
  if (got >= *wanted) return;
  char msg[320];
  std::snprintf(msg, sizeof msg,
                "--require-quality %s: the simulator predicts %s for this job (max deviation "
                "%.1f µm, coverage %.2f %%, dose ratio %.2f); nothing was fired — lower --speed "
                "or change --corner",
                name.c_str(), std::string(to_string(got)).c_str(), r.quality->max_deviation_um,
                100 * r.quality->coverage, r.quality->dose_ratio_max);
  throw InputError(msg);
}

int run_mark(const MarkArgs& a) {
  const JobSpec spec = make_spec(a);
  for (const auto& [path, option] : {std::pair{a.preview, "--preview"}, {a.dose_png, "--dose-png"},
                                     {a.trace, "--trace"}})
    check_output_file(path, option);
  const InjectArg inject = a.inject.empty() ? InjectArg{} : parse_inject(a.inject);
  if (!a.require_quality.empty())
    require_quality(spec, a.require_quality, a.head.laser_rise_us * 1e-6);

  SimSettings sim_settings;
  sim_settings.fault_at = inject.device_fault_at;
  sim_settings.trace = !a.trace.empty();
  sim_settings.laser_rise_s = a.head.laser_rise_us * 1e-6;
  const std::unique_ptr<Device> device = open_device(a.device, spec, sim_settings);
  auto* scanner = dynamic_cast<SimScanner*>(device.get());
  if (!scanner && (!a.preview.empty() || !a.dose_png.empty() || !a.trace.empty()))
    throw InputError("--preview, --dose-png and --trace need the simulated scanner (--device sim)");

  JobOptions options;
  options.virtual_time = a.virtual_time;
  options.stop = &interrupt_flag();
  options.inject = inject.drain;
  if (!a.json && isatty(STDERR_FILENO)) options.progress = progress_printer();
  const JobResult r =
      scanner ? run_job_simulated(spec, options, *scanner) : run_job(spec, options, *device);
  if (scanner) {
    if (!a.preview.empty())
      write_file_whole(a.preview, [&](const std::string& tmp) {
        write_mark_preview(r.job.plan, scanner->dose(), tmp);
      });
    if (!a.dose_png.empty())
      write_file_whole(a.dose_png, [&](const std::string& tmp) { write_dose_png(scanner->dose(), tmp); });
    if (!a.trace.empty()) write_trace(scanner->trace(), a.trace);
  }
  if (a.json) {
    std::cout << to_json(a, spec, r, device->describe().name).dump() << "\n";
  } else {
    print_summary(spec, r);
    if (!a.preview.empty()) std::printf("wrote %s\n", a.preview.c_str());
  }
  if (r.outcome != JobOutcome::done) {
    print_stop(r, spec, interrupt_flag().requested());
    return r.outcome == JobOutcome::aborted ? kExitInterrupted : 1;
  }
  if (r.quality && classify(*r.quality) == QualityClass::poor)
    std::fprintf(stderr,
                 "marker: warning: poor mark predicted (max deviation %.1f µm, coverage %.2f %%, "
                 "dose ratio %.2f): lower --speed\n",
                 r.quality->max_deviation_um, 100 * r.quality->coverage, r.quality->dose_ratio_max);
  return 0;
}

}  // namespace

Command make_mark_command() {
  auto a = std::make_shared<MarkArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("mark", "mark the text on a device (default: the simulated scanner)");
        sub->add_option("text", a->text, "text to mark (UTF-8; \\n starts a new line)")->required();
        add_layout_options(*sub, a->layout);
        sub->add_option("--device", a->device, "device: sim (the simulated scanner)")->capture_default_str();
        add_head_options(*sub, a->head, true);
        sub->add_option("--order", a->order, "stroke order: glyph, shortest (least jumping)")->capture_default_str();
        sub->add_option("--speed", a->speed,
                        "marking speed, mm/s, or auto: the fastest (up to 1000 mm/s) at which the "
                        "head's lag shrinks the tightest curve by at most 8 µm")
            ->capture_default_str();
        add_pen_options(*sub, a->pen, false);
        sub->add_option("--preview", a->preview,
                        "write the marked result: dose under the planned path (.png or .svg)");
        sub->add_option("--dose-png", a->dose_png, "write the raw dose raster as a PNG");
        sub->add_option("--trace", a->trace,
                        "write one CSV row per sample: t_s,cmd_x_mm,cmd_y_mm,laser,beam_x_mm,beam_y_mm");
        sub->add_option("--inject", a->inject,
                        "fault injection: underrun@N, abort@N or fault@N (N: sample index)");
        sub->add_option("--require-quality", a->require_quality,
                        "refuse to fire unless the simulator predicts this class: high, good");
        sub->add_flag("--virtual-time", a->virtual_time,
                      "drain as fast as the device accepts (device time is still reported)");
        sub->add_flag("--json", a->json, "print one JSON object with the job's figures");
        return sub;
      },
      [a] { return run_mark(*a); });
}

}  // namespace mark::cli
