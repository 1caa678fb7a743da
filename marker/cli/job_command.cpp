// `marker job check FILE [--set NAME=VALUE ...] [--json]`: validates a job file and prints what
// its next part would look like (every object laid out and planned, nothing marked, no store
// opened, nothing written).
// `marker job new -o FILE --text TEMPLATE [layout, pen and counter options]`: writes a job file
// from command-line options, so nobody has to write JSON by hand to start.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/cli/production_options.hpp"
#include "marker/job/auto_speed.hpp"
#include "marker/limits/counter_limits.hpp"
#include "marker/limits/pen_limits.hpp"
#include "marker/output/output_file.hpp"
#include "marker/production/part_texts.hpp"
#include "marker/production/text_repeats.hpp"
#include "marker/vars/clock.hpp"

namespace mark::cli {
namespace {

struct CheckArgs {
  std::string file;
  std::vector<std::string> sets;
  bool json = false;
};

struct NewArgs {
  std::string output;
  std::string text;
  std::string object = "text";
  LayoutArgs layout;
  std::string head = "SL10";
  double spot_um = 40;
  std::string pen = "default";
  std::string corner = "blanking";
  std::string speed = "auto";  // mm/s, or auto: from the first part's figure and the head
  std::optional<double> jump_speed_mm_s, tick_us;
  double power_pct = 100, frequency_khz = 30, pulse_width_ns = 0;
  std::string source = "fiber";
  int passes = 1;
  long long start = 1, step = 1, marks_per_serial = 1;
  int width = 0;
  std::optional<long long> limit;
  std::string at_limit = "stop", alphabet = "decimal", padding = "keep", reset = "never";
  std::string time_zone = "local";
  std::string device = "sim";
  std::string shifts;  // "A=06:00,B=14:00"
  std::vector<std::string> vars;
  bool force = false;
};

int run_check(const CheckArgs& a) {
  const JobFile job = read_job_file(a.file);
  const auto variables = job_variables(job, parse_sets(a.sets));
  std::vector<std::string> warnings;
  const JobFonts fonts(job, &warnings);
  for (const std::string& w : warnings) std::cerr << "marker: warning: " << w << "\n";
  for (const std::string& w : text_repeat_warnings(job)) std::cerr << "marker: warning: " << w << "\n";
  // The first part of a fresh store (the store, if any, is not read: checking a job touches
  // nothing but the job, its fonts and its data list).
  std::map<std::string, std::int64_t> serials;
  const std::optional<DataList> data = job.data ? std::optional(load_data_list(job)) : std::nullopt;
  const std::vector<ObjectText> texts =
      first_part_texts(job, variables, SystemClock().now(), &serials, data ? &*data : nullptr);

  nlohmann::json out = {{"job", job.job_name}, {"file", a.file}, {"head", job.head.name},
                        {"field_mm", job.head.field_mm}, {"spot_diameter_um", job.head.spot_diameter_um},
                        {"objects", nlohmann::json::array()}, {"serials", serials},
                        {"required_variables", job.required_variables()}};
  double total_s = 0;
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    const JobObject& o = job.objects[i];
    const JobPen& pen = job.pens.at(o.pen);
    CompiledJob compiled;
    try {
      compiled = compile_job(object_spec(job, o, texts[i].text, fonts));
    } catch (const InputError& e) {
      throw InputError(object_place(job, i) + e.what());
    }
    // Pulses land v/f apart; overlap against the spot (dynamics.md §4.2).
    const double spacing_um = pen.motion.mark_speed_mm_s / (pen.laser.frequency_khz * 1e3) * 1e3;
    const double overlap = 1 - spacing_um / job.head.spot_diameter_um;
    const double duration_s = compiled.plan.duration_s();  // every pass
    total_s += duration_s;
    const Box b = compiled.figure.bounds();
    out["objects"].push_back({{"name", o.name}, {"kind", o.kind}, {"pen", o.pen},
                              {"text", texts[i].text}, {"glyphs", compiled.figure.glyphs.size()},
                              {"strokes", compiled.plan.strokes},
                              {"planned_time_s", duration_s},
                              {"bounds_mm", {b.min.x(), b.min.y(), b.max.x(), b.max.y()}},
                              {"power_pct", pen.laser.power_pct},
                              {"frequency_khz", pen.laser.frequency_khz},
                              {"pulse_width_ns", pen.laser.pulse_width_ns},
                              {"source", std::string(to_string(pen.laser.source))},
                              {"passes", pen.passes},
                              {"pulse_spacing_um", spacing_um}, {"pulse_overlap_fraction", overlap}});
  }
  out["planned_time_s"] = total_s;
  if (a.json) {
    std::cout << out.dump() << "\n";
    return 0;
  }
  std::printf("%s: job \"%s\" on %s (field %.0f mm, spot %.0f µm): %zu object(s), planned %.3f s a part\n",
              a.file.c_str(), job.job_name.c_str(), job.head.name.c_str(), job.head.field_mm,
              job.head.spot_diameter_um, job.objects.size(), total_s);
  for (const auto& o : out["objects"]) {
    std::string text = o["text"].get<std::string>();
    for (char& c : text)
      if (c == '\n') c = '|';
    std::printf("  %-10s pen %-8s \"%s\": %d glyphs, %d strokes, %.3f s; %.0f %% at %.0f kHz, "
                "pulses %.1f µm apart (overlap %.0f %%)%s\n",
                o["name"].get<std::string>().c_str(), o["pen"].get<std::string>().c_str(),
                text.c_str(), o["glyphs"].get<int>(), o["strokes"].get<int>(),
                o["planned_time_s"].get<double>(), o["power_pct"].get<double>(),
                o["frequency_khz"].get<double>(), o["pulse_spacing_um"].get<double>(),
                100 * o["pulse_overlap_fraction"].get<double>(),
                o["pulse_overlap_fraction"].get<double>() < 0 ? " — separate dots" : "");
  }
  for (const auto& [name, value] : serials) std::printf("  counter %s starts at %lld\n", name.c_str(), static_cast<long long>(value));
  for (const std::string& v : job.required_variables())
    std::printf("  variable %s has no default: mark with --set %s=VALUE\n", v.c_str(), v.c_str());
  std::printf("ok\n");
  return 0;
}

double speed_number(const std::string& speed) {
  const std::optional<double> v = parse_number(speed);
  if (!v) throw InputError("--speed: '" + speed + "' is neither auto nor a number (range: " + kSpeedRange.text() + ")");
  check_range("--speed", *v, kSpeedRange, speed);
  return *v;
}

nlohmann::ordered_json new_job_json(const NewArgs& a) {
  nlohmann::ordered_json layout = {{"template", a.text}, {"pen", a.pen}};
  const LayoutArgs& l = a.layout;
  layout["font"] = l.font;
  layout["height_mm"] = l.height_mm;
  if (l.width_factor != 1) layout["width_factor"] = l.width_factor;
  if (l.gap_mm != 0) layout["gap_mm"] = l.gap_mm;
  if (l.line_spacing != 1) layout["line_spacing"] = l.line_spacing;
  if (l.align != "left") layout["align"] = l.align;
  layout["x_mm"] = l.x_mm;
  layout["y_mm"] = l.y_mm;
  if (l.angle_deg != 0) layout["angle_deg"] = l.angle_deg;
  if (l.italic_deg != 0) layout["italic_deg"] = l.italic_deg;
  if (l.mirror) layout["mirror"] = true;
  if (l.replace_missing) layout["replace_missing"] = true;
  if (!l.circle.empty()) {
    const LayoutOptions o = to_layout_options(l);
    nlohmann::ordered_json c = {{"cx_mm", o.circle->center.x()}, {"cy_mm", o.circle->center.y()},
                        {"radius_mm", o.circle->radius_mm}, {"inside", o.circle->inside}};
    if (o.circle->start_angle_deg) c["start_angle_deg"] = *o.circle->start_angle_deg;
    layout["circle"] = c;
  }
  nlohmann::ordered_json object = {{"name", a.object}, {"kind", "text"}};
  object.update(layout);

  nlohmann::ordered_json pen = {{"corner", a.corner}, {"speed_mm_s", a.speed == "auto" ? 1000.0 : speed_number(a.speed)},
                        {"power_pct", a.power_pct}, {"frequency_khz", a.frequency_khz},
                        {"pulse_width_ns", a.pulse_width_ns}, {"source", a.source}, {"passes", a.passes}};
  if (a.jump_speed_mm_s) pen["jump_speed_mm_s"] = *a.jump_speed_mm_s;
  if (a.tick_us) pen["tick_us"] = *a.tick_us;

  nlohmann::ordered_json job = {{"format", kJobFormat},
                        {"name", std::filesystem::path(a.output).stem().string()},
                        {"device", a.device},
                        {"head", {{"model", a.head}, {"spot_diameter_um", a.spot_um}}},
                        {"field_mm", l.field_mm},
                        {"time_zone", a.time_zone}};
  if (!a.shifts.empty()) {
    nlohmann::ordered_json shifts = nlohmann::ordered_json::array();
    std::size_t pos = 0;
    while (pos <= a.shifts.size()) {
      const std::size_t end = std::min(a.shifts.find(',', pos), a.shifts.size());
      const std::string item = a.shifts.substr(pos, end - pos);
      const std::size_t eq = item.find('=');
      if (eq == std::string::npos)
        throw InputError("--shifts '" + a.shifts + "': expected CODE=HH:MM,… e.g. A=06:00,B=14:00,C=22:00");
      shifts.push_back({{"code", item.substr(0, eq)}, {"start", item.substr(eq + 1)}});
      pos = end + 1;
    }
    job["shifts"] = shifts;
  }
  const auto vars = parse_sets(a.vars);
  if (!vars.empty()) job["variables"] = nlohmann::ordered_json(vars);
  nlohmann::ordered_json counters = nlohmann::ordered_json::object();
  for (const std::string& name : TextTemplate::parse(a.text, "--text").counters()) {
    nlohmann::ordered_json c = {{"start", a.start}, {"step", a.step}, {"width", a.width},
                        {"padding", a.padding}, {"alphabet", a.alphabet}, {"at_limit", a.at_limit},
                        {"marks_per_serial", a.marks_per_serial}, {"reset", a.reset}};
    if (a.limit) c["limit"] = *a.limit;
    counters[name] = c;
  }
  if (!counters.empty()) job["counters"] = counters;
  job["pens"] = {{a.pen, pen}};
  job["objects"] = nlohmann::json::array({object});
  return job;
}

// --speed auto: the speed `marker mark --speed auto` picks for the first part's text, rounded
// down to 10 mm/s, written into the pen so the job marks the same way every time.
double auto_pen_speed(const nlohmann::ordered_json& j, const std::string& source) {
  const JobFile job = parse_job(j.dump(), source);
  const JobObject& o = job.objects.front();
  const std::vector<ObjectText> texts = first_part_texts(job, job.variables, SystemClock().now());
  const JobFonts fonts(job);
  const JobSpec spec = object_spec(job, o, texts.front().text, fonts);
  const double v = auto_mark_speed_mm_s(layout_text(spec.text, *spec.font, spec.layout), job.head);
  return std::max(10.0, std::floor(v / 10) * 10);
}

int run_new(const NewArgs& a) {
  check_output_path("--output", a.output, {".json"});
  if (std::filesystem::exists(a.output) && !a.force)
    throw InputError(a.output + " exists; give --force to replace it");
  nlohmann::ordered_json j = new_job_json(a);
  if (a.speed == "auto") j["pens"][a.pen]["speed_mm_s"] = auto_pen_speed(j, a.output);
  const std::string text = j.dump(2) + "\n";
  parse_job(text, a.output);  // what we write must read back: the same checks as any job file
  write_file_whole(a.output, text);  // a reader never sees half a job
  std::printf("wrote %s\n", a.output.c_str());
  return 0;
}

}  // namespace

Command make_job_command() {
  auto check = std::make_shared<CheckArgs>();
  auto created = std::make_shared<NewArgs>();
  auto subs = std::make_shared<std::pair<CLI::App*, CLI::App*>>();
  return Command(
      [=](CLI::App& app) {
        auto* job = app.add_subcommand("job", "job files: check one, or write a new one");
        job->require_subcommand(1);
        auto* c = job->add_subcommand("check", "validate a job file and show what its next part would be");
        c->add_option("file", check->file, "job file (.json)")->required();
        c->add_option("--set", check->sets, "variable value NAME=VALUE (repeatable)");
        c->add_flag("--json", check->json, "print one JSON object");
        auto* n = job->add_subcommand("new", "write a job file from command-line options");
        NewArgs& a = *created;
        n->add_option("-o,--output", a.output, "job file to write")->required();
        n->add_option("--text", a.text, "template: text with {serial}, {date:%y%j}, {var:lot}, {shift}")->required();
        n->add_option("--name", a.object, "the object's name")->capture_default_str();
        add_layout_options(*n, a.layout);
        n->add_option("--head", a.head, "scan head: SL10, SL14, cheap, SA14")->capture_default_str();
        add_ranged_option(*n, "--spot", a.spot_um, "focused spot diameter, µm", kSpotRange)->capture_default_str();
        n->add_option("--pen", a.pen, "the pen's name")->capture_default_str();
        n->add_option("--corner", a.corner, "corner strategy: blanking, delays, none")->capture_default_str();
        n->add_option("--speed", a.speed,
                      "marking speed, mm/s (at most the head's limit), or auto: what `mark --speed auto` "
                      "picks for the first part's text, written into the pen")
            ->capture_default_str();
        add_ranged_option(*n, "--jump-speed", a.jump_speed_mm_s,
                          "jump speed, mm/s (default: the head's; at most its limit)", kSpeedRange);
        add_ranged_option(*n, "--tick", a.tick_us, "locus tick, µs (default 10; at most 20 % of the head's τ)",
                          kTickRange);
        add_ranged_option(*n, "--power", a.power_pct, "laser power, %", kPowerRange)->capture_default_str();
        add_ranged_option(*n, "--frequency", a.frequency_khz, "pulse frequency, kHz", kFrequencyRange)
            ->capture_default_str();
        add_ranged_option(*n, "--pulse-width", a.pulse_width_ns, "MOPA pulse width, ns (0: the source's default)",
                          kPulseWidthRange)
            ->capture_default_str();
        n->add_option("--source", a.source, "laser source: fiber (Q-switched), mopa, co2, uv")
            ->check(CLI::IsMember({"fiber", "mopa", "co2", "uv"}))
            ->capture_default_str();
        add_ranged_option(*n, "--passes", a.passes, "times each object is marked", kPassesRange)->capture_default_str();
        add_ranged_option(*n, "--start", a.start, "counters: first value", kCounterValueRange)->capture_default_str();
        add_ranged_option(*n, "--step", a.step, "counters: step (negative counts down)", kCounterStepRange)
            ->capture_default_str();
        add_ranged_option(*n, "--width", a.width, "counters: digits (0: as many as needed)", kCounterWidthRange)
            ->capture_default_str();
        add_ranged_option(*n, "--limit", a.limit, "counters: last value", kCounterValueRange);
        n->add_option("--at-limit", a.at_limit, "counters: stop or wrap")->capture_default_str();
        n->add_option("--alphabet", a.alphabet, "counters: decimal, hex, base36, base33")->capture_default_str();
        n->add_option("--padding", a.padding, "counters: keep, suppress, blank")->capture_default_str();
        add_ranged_option(*n, "--marks-per-serial", a.marks_per_serial, "counters: parts per value",
                          kMarksPerSerialRange)
            ->capture_default_str();
        n->add_option("--reset", a.reset, "counters: never, midnight, shift")->capture_default_str();
        n->add_option("--device", a.device, "the device the job marks on: sim, or the station's board: lmc, lmc:SERIAL")->capture_default_str();
        n->add_option("--time-zone", a.time_zone, "dates, shifts and resets: local, UTC or e.g. Europe/Berlin")->capture_default_str();
        n->add_option("--shifts", a.shifts, "shift codes and start times: A=06:00,B=14:00,C=22:00");
        n->add_option("--var", a.vars, "variable default NAME=VALUE (repeatable)");
        n->add_flag("--force", a.force, "replace an existing file");
        *subs = {c, n};
        return job;
      },
      [=] { return subs->first->parsed() ? run_check(*check) : run_new(*created); });
}

}  // namespace mark::cli
