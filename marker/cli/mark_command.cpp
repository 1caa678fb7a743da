// `marker mark TEXT [layout options] [--fill hatch …] [--code SYMBOLOGY:DATA --code-…]
//  [--device sim|lmc[:SERIAL]|lmc-capture:FILE] [--head SL10|SL14|cheap|SA14]
//  [--head-model first|second] [--laser-rise-us US] [--plant K=V,…] [--corner blanking|delays|none]
//  [--speed MM_S|auto] [--lookahead] [--feed-forward] [--head-profile FILE] [pen parameters]
//  [--power PCT] [--frequency KHZ] [--pulse-width NS] [--preview FILE.png] [--dose-png FILE.png]
//  [--virtual-time] [--json] [--inject KIND@N] [--trace FILE.csv] [--require-quality high|good]
//  [--require-grade A|B|C|D] [--camera KEY=VALUE,…] [--reader zxing|libdmtx|zbar]
//  [LMC options]`
// `marker mark --job FILE [--set NAME=VALUE …] [--count N] [--store PATH|URL] [--station NAME]
//  [--remark ID]`: the production run, in mark_job.cpp.
// The main job: real time by default (the drain paced at the tick, so the line memory is written
// while it is read), quality figures against the laid-out text. Ctrl-C / SIGTERM put the laser
// out within one drain block; the command then says where it stopped and exits 130. Outline-font
// text can be hatch-filled; a code marked with the text is read back off the simulated part.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "driver/lmc/lmc_spec.hpp"
#include "driver/sim/grey_png.hpp"
#include "driver/sim/quality_class.hpp"
#include "fonts/catalog.hpp"
#include "marker/cli/code_options.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/device_factory.hpp"
#include "marker/cli/head_options.hpp"
#include "marker/cli/inject_option.hpp"
#include "marker/cli/production_options.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/cli/lmc_options.hpp"
#include "marker/cli/mark_job.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/cli/pen_options.hpp"
#include "marker/cli/unread_options.hpp"
#include "marker/cli/plant_option.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/codes/code_json.hpp"
#include "marker/job/auto_speed.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/job/job_json.hpp"
#include "marker/job/mark_requirement.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "marker/limits/code_settings.hpp"
#include "marker/limits/device_settings.hpp"
#include "marker/limits/fill_settings.hpp"
#include "marker/limits/marking_settings.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/output/output_file.hpp"
#include "marker/preview/mark_preview.hpp"
#include "marker/preview/sim_outputs.hpp"

namespace mark::cli {
namespace {

struct MarkArgs {
  std::string text;
  LayoutArgs layout;
  std::string device;
  HeadArgs head;
  PenArgs pen;
  std::string order;
  std::string speed;  // mm/s, or auto: from the figure's tightest curve and the head
  std::string preview;
  std::string dose_png;
  std::string trace;
  std::string inject;
  std::string require_quality;
  std::string require_grade;
  LaserSettings laser;
  std::string source{kLaserSource.value};  // laser.source, as --source names it
  LmcArgs lmc;
  std::string code;  // SYMBOLOGY:DATA
  CodeArgs code_args;
  VerifyArgs verify;
  bool virtual_time = false;
  bool json = false;
  MarkJobArgs production;  // --job and its options
};

// The spec and its one layout: the figure laid out (filled, with its codes) before the pen is
// made, since the automatic speed comes from the figure's tightest curve. The plan is made once
// the device (its level) is known.
struct PreparedMark {
  JobSpec spec;
  CompiledJob laid_out;  // figure and codes; no plan yet
  double layout_s = 0;   // wall time of the layout (part of the job's compile time)
};

PreparedMark prepare_mark(const MarkArgs& a) {
  JobSpec spec;
  spec.head = simulated_head(a.head);
  spec.head.field_mm = a.layout.field_mm;
  spec.text = unescape_text(a.text);
  if (!spec.text.empty()) {
    Warnings warnings;
    spec.font = open_font(a.layout.font, &warnings);
    for (const std::string& w : warnings) std::cerr << "marker: warning: " << w << "\n";
  }
  spec.layout = to_layout_options(a.layout);
  spec.order = parse_stroke_order(a.order);
  spec.verify = to_verify_options(a.verify);
  const double beam_radius_mm = a.verify.beam_diameter_mm / 2;
  spec.fill = to_fill(a.layout, beam_radius_mm);
  if (!a.code.empty()) {
    const std::size_t colon = a.code.find(':');
    if (colon == std::string::npos)
      throw InputError("--code '" + a.code + "': expected SYMBOLOGY:DATA, e.g. datamatrix:SN0042");
    spec.codes.push_back(to_code_object(a.code.substr(0, colon), a.code.substr(colon + 1), a.code_args,
                                        to_fill_options(a.layout.hatch, beam_radius_mm), "code-"));
  }
  // A text leaving the field is refused with what to change (the plan is checked again, with
  // its blanking lines, before the first sample).
  const auto t0 = std::chrono::steady_clock::now();
  CompiledJob laid_out = lay_out_job(spec, kFieldRemedy);
  const double layout_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double speed_mm_s = 0;
  if (a.speed == kAutoSpeed) {
    // The whole figure: filled letters' contour arcs and a code's dots count too.
    speed_mm_s = auto_mark_speed_mm_s(laid_out.figure, spec.head);
  } else {
    // Checked here and only here: the range a job file's pen speed has on this head.
    speed_mm_s = *number_or_word(kMarkSpeed, a.speed, kAutoSpeed, head_speed_range(kMarkSpeed, spec.head));
  }
  PenArgs pen = a.pen;
  pen.speed_mm_s = speed_mm_s;
  spec.pen = make_pen(pen, spec.head);
  spec.laser = a.laser;
  spec.laser.source = *parse_laser_source(a.source);
  check_laser_settings(spec.laser, "--source " + a.source + ": ");
  return {std::move(spec), std::move(laid_out), layout_s};
}

nlohmann::json to_json(const MarkArgs& a, const JobSpec& spec, const JobOptions& options,
                       const JobResult& r, const std::string& device_name) {
  nlohmann::json j = job_result_json(r);
  j["text"] = spec.text;
  j["font"] = a.layout.font;
  j["height_mm"] = spec.layout.height_mm;
  j["head"] = spec.head.name;
  j["head_model"] = spec.head.second_order ? "second" : "first";
  j["laser_rise_us"] = a.head.laser_rise_us;
  j["plant"] = plant_text(parse_plant_option(a.head.plant));
  j["lookahead"] = spec.pen.lookahead || spec.pen.feed_forward();
  j["feed_forward"] = spec.pen.feed_forward();
  j["device"] = device_name;
  j["corner"] = to_string(spec.pen.corner);
  j["speed_mm_s"] = spec.pen.mark_speed_mm_s;
  j["tick_s"] = spec.pen.tick_s;
  j["line_memory_samples"] = options.memory_samples;
  if (!r.codes.empty()) {
    j["codes"] = nlohmann::json::array();
    for (std::size_t k = 0; k < r.codes.size(); ++k)
      j["codes"].push_back(code_to_json(r.job.codes[k], spec.codes[k].spec, r.codes[k]));
  }
  return j;
}

void print_summary(const JobSpec& spec, const JobResult& r, const std::string& device) {
  // A mark that stopped did not mark its glyphs: it was planned with them (print_stop says where).
  std::printf("%s %zu glyphs (%zu strokes, %zu commands) on %s, %s corners, %.0f mm/s\n",
              r.outcome == JobOutcome::done ? "marked" : "planned", r.glyphs, r.strokes, r.commands, device.c_str(),
              std::string(to_string(spec.pen.corner)).c_str(), spec.pen.mark_speed_mm_s);
  std::printf("mark time %.4f s (device), %llu samples, compile %.1f µs, jumps %.1f mm, "
              "underruns %llu\n",
              r.mark_time_s, static_cast<unsigned long long>(r.samples), r.compile_time_s * 1e6,
              r.jump_length_mm, static_cast<unsigned long long>(r.drain.underrun_events));
  if (r.quality)
    std::printf("quality: %s — %s, rms %.1f µm, overshoot %.1f µm\n",
                std::string(to_string(classify(*r.quality))).c_str(), quality_figures(*r.quality).c_str(),
                r.quality->rms_deviation_um, r.quality->overshoot_um);
  if (r.pulses)
    std::printf("pulses: %.1f µm apart at %.0f kHz on a %.0f µm spot, overlap %.0f %%%s\n",
                r.pulses->spacing_max_um, r.pulses->frequency_khz, r.pulses->spot_diameter_um,
                100 * r.pulses->overlap(), r.pulses->separate_dots() ? " — separate dots" : "");
  for (std::size_t k = 0; k < r.codes.size(); ++k) {
    const CodeVerification& v = r.codes[k];
    const PlacedCode& c = r.job.codes[k];
    std::printf("code %zu: %s %dx%d, module %.0f µm, readers (%s): %s", k + 1,
                std::string(to_string(c.matrix.symbology)).c_str(), c.matrix.rows, c.matrix.cols, v.module_um,
                v.decided_by.c_str(), v.data_match ? "pass" : v.decoded ? "FAIL (misread or not agreed)" : "NOT decoded");
    if (v.decoded) std::printf(" '%s'", printable_bytes(v.decoded_data).c_str());
    if (v.grade) std::printf(", grade %c", grade_letter(v.grade->overall));
    std::printf(", %zu modules wrong\n", v.modules_wrong);
  }
}

// Where a job that did not finish stopped, on one line (stderr).
void print_stop(const JobResult& r, const JobSpec& spec, bool interrupted, DeviceLevel level) {
  const double t = static_cast<double>(r.stopped_at) * spec.pen.tick_s;
  std::string why = r.outcome == JobOutcome::aborted
                        ? (interrupted ? "interrupted" : "aborted")
                        : "failed (" + std::string(to_string(r.fault->category)) + ": " +
                              r.fault->message + ")";
  if (level == DeviceLevel::commands) {
    // A vector board: the stop point is a device command; its own clock is not the locus tick.
    std::fprintf(stderr, "marker: mark %s at device command %llu: %.1f %% of the ink marked at most\n",
                 why.c_str(), static_cast<unsigned long long>(r.stopped_at), 100 * r.ink_marked);
    return;
  }
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

// --require-quality and --require-grade: the simulator predicts the mark of `job` (planned for a
// sample-level device; virtual time, no device touched) and judges it as a production part is
// judged (mark_requirement.hpp); short of it, the job is refused before anything fires.
void require_prediction(const JobSpec& spec, const CompiledJob& job, const MarkArgs& a) {
  MarkRequirement require;
  std::string asked;
  if (!a.require_quality.empty()) {
    require.quality = parse_quality_class(a.require_quality);
    if (!require.quality || *require.quality == QualityClass::poor)
      throw InputError("--require-quality '" + a.require_quality + "' is not one of high, good");
    asked = "--require-quality " + a.require_quality;
  }
  if (!a.require_grade.empty()) {
    require.code_grade = parse_required_grade(a.require_grade, "--require-grade");
    if (spec.codes.empty())
      throw InputError("--require-grade " + a.require_grade + ": the job marks no code (give --code)");
    asked += (asked.empty() ? "" : ", ") + ("--require-grade " + a.require_grade);
  }
  if (const auto why = predicted_shortfall(spec, job, require, a.head.laser_rise_us * 1e-6))
    throw InputError(asked + ": the simulator predicts " + *why + "; nothing was fired");
}

int run_mark(const MarkArgs& a) {
  if (a.text.empty() && a.code.empty()) throw InputError("mark: give the text to mark (or --code), or --job FILE");
  PreparedMark prepared = prepare_mark(a);
  const JobSpec& spec = prepared.spec;
  for (const CodeObject& c : spec.codes) check_reader_choice(spec.verify.reading.reader, place_encoded(c), "--reader");
  // Every file the job writes is checked before anything is fired.
  check_standard_output({{"--preview", &a.preview}, {"--dose-png", &a.dose_png}, {"--trace", &a.trace}}, a.json);
  if (!a.preview.empty()) check_output_path("--preview", a.preview, {".svg", ".png"});
  if (!a.dose_png.empty()) check_output_path("--dose-png", a.dose_png, {".png"});
  if (!a.trace.empty()) check_output_path("--trace", a.trace);
  const InjectArg inject = a.inject.empty() ? InjectArg{} : parse_inject(a.inject);
  if (inject.store) throw InputError("--inject " + a.inject + ": the store applies to a production run: give --job FILE");
  // One plan for the sample-level prediction (quality and code grades), kept for the run when
  // the device takes samples too (the simulated scanner): the text is laid out and planned once
  // per mark.
  const auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  std::optional<CompiledJob> sample_plan;
  double plan_s = 0;
  if (!a.require_quality.empty() || !a.require_grade.empty()) {
    const auto t = std::chrono::steady_clock::now();
    sample_plan = plan_job(prepared.laid_out, spec, DeviceLevel::samples);
    plan_s = seconds_since(t);
  }
  if (sample_plan) require_prediction(spec, *sample_plan, a);

  SimSettings sim_settings;
  sim_settings.fault_at = inject.device_fault_at;
  sim_settings.trace = !a.trace.empty();
  sim_settings.laser_rise_s = a.head.laser_rise_us * 1e-6;
  sim_settings.plant = parse_plant_option(a.head.plant);
  sim_settings.virtual_time = a.virtual_time;
  // Refused before the device opens (a capture file would be begun): only the simulated head
  // (alone or behind the emulated board) has a plant.
  if (!sim_settings.plant.is_model() && a.device != "sim") {
    const auto board = lmc::parse_lmc_spec(a.device);
    if (!board || !board->emulated)
      throw InputError("--plant '" + a.head.plant + "': a real board drives its own head; the plant is the simulated one's");
  }
  const OpenedDevice opened = open_device(a.device, spec, sim_settings, a.lmc);
  const std::unique_ptr<Device>& device = opened.device;
  const SimScanner* scanner = opened.simulator ? &opened.simulator->scanner() : nullptr;
  if (!scanner && (!a.preview.empty() || !a.dose_png.empty() || !a.trace.empty()))
    throw InputError("--preview, --dose-png and --trace need a simulated scanner (--device sim or lmc-emulated)");

  JobOptions options;
  options.virtual_time = a.virtual_time;
  options.stop = &interrupt_flag();
  options.inject = inject.drain;
  if (!a.json && isatty(STDERR_FILENO)) options.progress = progress_printer();
  const DeviceLevel level = device->describe().level;
  std::optional<CompiledJob> job;
  if (sample_plan && level == DeviceLevel::samples) {
    job = std::move(sample_plan);
  } else {
    const auto t = std::chrono::steady_clock::now();
    job = plan_job(std::move(prepared.laid_out), spec, level);
    plan_s = seconds_since(t);
  }
  options.compiled_s = prepared.layout_s + plan_s;
  options.evaluator = opened.simulator.get();
  const JobResult r = run_compiled_job(spec, std::move(*job), options, *device);
  // A job stopped by Ctrl-C leaves no files: what it would show is not the part on the machine's
  // table. A failed job's files show how far it got.
  std::optional<GreyImage> picture;
  if (scanner && !interrupt_flag().requested()) {
    if (!a.preview.empty()) write_mark_preview(r.job.plan, scanner->picture_dose(), a.preview);
    if (!a.dose_png.empty()) {
      // The part itself; a job with an inverted code is on a dark part.
      bool dark_part = false;
      for (const CodeObject& c : spec.codes) dark_part = dark_part || c.layout.invert;
      picture = dose_part_picture(scanner->picture_dose(), spec.verify.response, spec.verify.camera.look, dark_part);
      write_file_whole(a.dose_png, encode_grey_png(*picture));
    }
    if (!a.trace.empty()) write_trace_csv(scanner->trace(), a.trace);
  }
  if (a.json) {
    nlohmann::json j = to_json(a, spec, options, r, device->describe().name);
    if (picture) j["dose_px_um"] = 1e6 / pixels_per_metre(picture->pixel_mm);
    std::cout << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  } else {
    print_summary(spec, r, device->describe().name);
    if (!a.preview.empty()) std::printf("wrote %s\n", a.preview.c_str());
  }
  if (r.outcome != JobOutcome::done) {
    print_stop(r, spec, interrupt_flag().requested(), device->describe().level);
    return r.outcome == JobOutcome::aborted ? kExitInterrupted : 1;
  }
  for (std::size_t k = 0; k < r.codes.size(); ++k)
    if (!r.codes[k].data_match)
      std::fprintf(stderr, "marker: warning: code %zu (%s) does not read back off the simulated mark\n", k + 1,
                   std::string(to_string(spec.codes[k].spec.symbology)).c_str());
  if (r.quality && classify(*r.quality) == QualityClass::poor)
    std::fprintf(stderr, "marker: warning: poor mark predicted (%s): lower --speed (or, for a pulse gap, raise --frequency)\n",
                 quality_figures(*r.quality).c_str());
  if (r.pulses && r.pulses->separate_dots())
    std::fprintf(stderr,
                 "marker: warning: pulses land %.1f µm apart on a %.0f µm spot: lit strokes show "
                 "as separate dots; raise --frequency or lower --speed\n",
                 r.pulses->spacing_max_um, r.pulses->spot_diameter_um);
  return 0;
}

// The options of `mark` that belong to one mode only: the command line's text and pen, or the
// job file's production run.
struct MarkModes {
  CLI::App* sub = nullptr;
  std::vector<const CLI::Option*> production;  // --job and what only it takes
  std::vector<const CLI::Option*> shared;      // either mode
};

// The options of this mark that nothing reads are refused (unread_options.hpp), before anything
// is laid out or opened.
void refuse_unread_mark_options(const CLI::App& sub, const MarkArgs& a) {
  refuse_unread_pen_options(sub, a.pen);
  const bool filled = a.layout.fill == "hatch", code = !a.code.empty();
  const SettingRef rule[] = {&kFillRule};
  refuse_unread(sub, rule, filled, "only a filled text reads it (give --fill hatch)");
  refuse_unread(sub, kHatchSettingList, filled || code, "only a hatch fill reads it (give --fill hatch, or --code)");
  refuse_unread(sub, kCodeSettingList, code, "only a code reads it (give --code SYMBOLOGY:DATA)", "code-");
  const SettingRef dot[] = {&kDotShape, &kDotSize};
  refuse_unread(sub, dot, a.code_args.style == "dot", "only dot-style modules read it (give --code-style dot)",
                "code-");
  refuse_unread(sub, kLmcSettingList, a.device != "sim", "only an LMC board reads it (give --device lmc…)");
}

int run_mark_mode(const MarkArgs& a, const MarkModes& modes) {
  const auto in = [](const std::vector<const CLI::Option*>& list, const CLI::Option* o) {
    return std::find(list.begin(), list.end(), o) != list.end();
  };
  if (a.production.job.empty()) {
    for (const CLI::Option* o : modes.production)
      if (o->count() > 0) throw InputError(o->get_name() + " applies to a production run: give --job FILE");
    refuse_unread_mark_options(*modes.sub, a);
    return run_mark(a);
  }
  for (const CLI::Option* o : modes.sub->get_options()) {
    if (o->count() == 0 || in(modes.production, o) || in(modes.shared, o)) continue;
    if (o->get_name() == kRequireQuality.name.flag || o->get_name() == kRequireGrade.name.flag)
      throw InputError(o->get_name() + " does not apply with --job: use the object's \"require\" in the job file "
                       "(docs/job-file.md)");
    throw InputError((o->nonpositional() ? o->get_name() : std::string("a text to mark")) +
                       " does not apply with --job: the job file sets it (see marker job check)");
  }
  MarkJobArgs job = a.production;
  job.device = modes.sub->count("--device") ? a.device : "";
  job.inject = a.inject;
  job.virtual_time = a.virtual_time;
  job.json = a.json;
  job.preview = a.preview;
  job.dose_png = a.dose_png;
  job.trace = a.trace;
  return run_mark_job(job);
}

}  // namespace

Command make_mark_command() {
  auto a = std::make_shared<MarkArgs>();
  auto modes = std::make_shared<MarkModes>();
  return Command(
      [a, modes](CLI::App& app) {
        auto* sub = app.add_subcommand("mark", "mark the text, or the parts of a job file, on a device (default: the simulated scanner)");
        modes->sub = sub;
        sub->add_option("text", a->text,
                        "text to mark (UTF-8; \\n starts a new line; may be \"\" with --code); or --job FILE");
        add_layout_options(*sub, a->layout);
        add_fill_options(*sub, a->layout);
        add_setting(*sub, kCodeData, a->code);
        add_code_options(*sub, a->code_args, "code-");
        add_verify_options(*sub, a->verify);
        modes->shared.push_back(add_setting(*sub, kDevice, a->device));
        add_head_options(*sub, a->head, true);
        add_setting(*sub, kOrder, a->order);
        add_setting(*sub, kMarkSpeed, a->speed, kAutoSpeed, kAutoSpeedHelp);
        add_pen_options(*sub, a->pen, false);
        // With --job: each part's files, named with {mark_id} / {serial} / {COUNTER}.
        modes->shared.push_back(sub->add_option(
            "--preview", a->preview,
            "write the marked result: dose under the planned path (.png or .svg; --job: each part's, "
            "name with {mark_id} or {serial})"));
        modes->shared.push_back(sub->add_option(
            "--dose-png", a->dose_png,
            "write the part itself at the dose raster's pixel (PNG, pixel size in pHYs and as dose_px_um)"));
        modes->shared.push_back(sub->add_option(
            "--trace", a->trace, "write one CSV row per sample: t_s,cmd_x_mm,cmd_y_mm,laser,beam_x_mm,beam_y_mm"));
        modes->shared.push_back(sub->add_option(
            "--inject", a->inject,
            "fault injection: underrun@N, abort@N or fault@N (N: sample index; with --job in every "
            "object's device job)"));
        add_setting(*sub, kRequireQuality, a->require_quality);
        add_setting(*sub, kRequireGrade, a->require_grade);
        modes->shared.push_back(add_setting(*sub, kVirtualTime, a->virtual_time));
        modes->shared.push_back(sub->add_flag(
            "--json", a->json, "print one JSON object with the job's figures (--job: one per part, JSON Lines)"));
        MarkJobArgs& p = a->production;
        modes->production = {
            sub->add_option("--job", p.job, "production run: mark the parts of this job file"),
            add_setting(*sub, kSet, p.sets),
            add_setting(*sub, kPartCount, p.count),
            add_setting(*sub, kStation, p.station),
            add_setting(*sub, kRemark, p.remark),
            add_setting(*sub, kRemarkReason, p.reason),
            add_setting(*sub, kAllowChangedJob, p.allow_changed_job),
            add_setting(*sub, kCreateCounters, p.create_counters)};
        // --store, --store-wait-ms, --store-attempts: the production run's.
        const std::size_t before = sub->get_options().size();
        add_store_options(*sub, p.store, true);
        for (std::size_t i = before; i < sub->get_options().size(); ++i) modes->production.push_back(sub->get_options()[i]);
        add_laser_options(*sub, a->laser);
        add_setting(*sub, kLaserSource, a->source);
        add_lmc_options(*sub, a->lmc);
        return sub;
      },
      [a, modes] { return run_mark_mode(*a, *modes); });
}

}  // namespace mark::cli
