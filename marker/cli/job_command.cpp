// `marker job check FILE [--set NAME=VALUE ...] [--json] [--preview OUT.png|svg [--store S]]`:
// validates a job file and prints what its next part would look like (every object laid out and
// planned, nothing marked, nothing written but the preview). Without --preview no store is
// opened: the part is a fresh store's first. With it, the part is the station's store's next
// (read-only, nothing consumed) and its picture is written (part_preview.hpp).
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
#include "marker/cli/part_preview.hpp"
#include "marker/cli/pen_options.hpp"
#include "marker/cli/production_options.hpp"
#include "marker/job/auto_speed.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/mark_requirement.hpp"
#include "marker/layout/figure_json.hpp"
#include "marker/limits/device_settings.hpp"
#include "marker/limits/head_settings.hpp"
#include "marker/limits/layout_settings.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/output/output_file.hpp"
#include "marker/production/object_clearance.hpp"
#include "marker/production/part_texts.hpp"
#include "marker/production/text_repeats.hpp"
#include "marker/vars/clock.hpp"

namespace mark::cli {
namespace {

struct CheckArgs {
  std::string file;
  std::vector<std::string> sets;
  bool json = false;
  std::string preview;  // the next part's picture
  StoreArgs store;      // where its values come from (--preview)
};

// The next part's counter values and data-list row for --preview: the store's, read-only; a
// store that does not exist yet gives the counters' starts and the first row (nullopt).
struct NextPart {
  std::map<std::string, std::int64_t> serials;
  std::size_t data_row = 0;
};
std::optional<NextPart> store_next_part(const CheckArgs& a, const JobFile& job, const DataList* data) {
  const std::string where = store_location(a.store.store);
  if (where.find("://") == std::string::npos && !std::filesystem::exists(where)) {
    std::cerr << "marker: no store at " << where << " yet: the preview is a fresh store's first part\n";
    return std::nullopt;
  }
  auto store = open_production_store(a.store, StoreAccess::read_only);
  NextPart next{next_serials(job, *store, SystemClock().now())};
  if (data) {
    const auto row = store->next_data_row({data, job.data->file, 0});
    if (!row)
      throw InputError("--preview: data list " + job.data->file + ": every row was taken by an earlier part (" +
                       std::to_string(data->size()) + " rows in the file): the next part would be refused");
    next.data_row = *row;
  }
  return next;
}

struct NewArgs {
  std::string output;
  std::string text;
  std::string object;
  LayoutArgs layout;
  std::string head;
  double spot_um = 0;
  std::string pen;
  std::string corner;
  std::string speed;  // mm/s, or auto: from the first part's figure and the head
  std::optional<double> jump_speed_mm_s, tick_us;
  LaserSettings laser;
  std::string source{kLaserSource.value};  // laser.source, as --source names it
  int passes = 1;
  long long start = 1, step = 1, marks_per_serial = 1;
  int width = 0;
  std::optional<long long> limit;
  std::string at_limit, alphabet, padding, reset;
  std::string time_zone;
  std::string device;
  std::string shifts;  // "A=06:00,B=14:00"
  std::vector<std::string> vars;
  bool force = false;
};

// Every object of a part compiled as marking would (laid out in the field, planned), what an
// object requires predicted, and the objects checked apart: InputError naming the object when
// the part could not be marked. `job check` and `job new` (nothing written that check refuses).
std::vector<CompiledJob> compile_part(const JobFile& job, const JobFonts& fonts, const std::vector<ObjectText>& texts) {
  std::vector<CompiledJob> objects;
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    const JobObject& o = job.objects[i];
    const JobSpec spec = object_spec(job, o, texts[i].text, fonts);
    try {
      objects.push_back(compile_job(spec));
      // What the object requires, predicted for the first part as every part is before it fires.
      if (o.require.any())
        if (const auto why = predicted_shortfall(spec, objects.back(), o.require))
          throw InputError("the simulator predicts " + *why + " (\"require\")");
    } catch (const InputError& e) {
      throw InputError(object_place(job, i) + e.what());
    }
  }
  check_objects_apart(job, objects);
  return objects;
}

int run_check(const CheckArgs& a) {
  if (!a.preview.empty()) check_output_path("--preview", a.preview, {".svg", ".png"});
  if (!a.store.store.empty() && a.preview.empty())
    throw InputError("--store applies to --preview (the next part's values): give --preview FILE");
  const JobFile job = read_job_file(a.file);
  const auto variables = job_variables(job, parse_sets(a.sets));
  std::vector<std::string> warnings;
  const JobFonts fonts(job, &warnings);
  for (const std::string& w : warnings) std::cerr << "marker: warning: " << w << "\n";
  for (const std::string& w : text_repeat_warnings(job)) std::cerr << "marker: warning: " << w << "\n";
  // The first part of a fresh store (the store, if any, is not read without --preview: checking a
  // job touches nothing but the job, its fonts and its data list); with --preview the store's next.
  std::map<std::string, std::int64_t> serials;
  const std::optional<DataList> data = job.data ? std::optional(load_data_list(job)) : std::nullopt;
  const auto next = a.preview.empty() ? std::nullopt : store_next_part(a, job, data ? &*data : nullptr);
  const std::vector<ObjectText> texts =
      first_part_texts(job, variables, SystemClock().now(), &serials, data ? &*data : nullptr,
                       next ? &next->serials : nullptr, next ? next->data_row : 0);

  nlohmann::json out = {{"job", job.job_name}, {"file", a.file}, {"head", job.head.name},
                        {"field_mm", job.head.field_mm}, {"spot_diameter_um", job.head.spot_diameter_um},
                        {"objects", nlohmann::json::array()}, {"serials", serials},
                        {"required_variables", job.required_variables()}};
  if (data) out["data_row"] = (next ? next->data_row : 0) + 1;  // 1: the first row after the header
  double total_s = 0;
  const std::vector<CompiledJob> objects = compile_part(job, fonts, texts);
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    const JobObject& o = job.objects[i];
    const JobPen& pen = job.pens.at(o.pen);
    const CompiledJob& compiled = objects[i];
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
                              {"bounds_mm", box_json(b)},
                              {"power_pct", pen.laser.power_pct},
                              {"frequency_khz", pen.laser.frequency_khz},
                              {"pulse_width_ns", pen.laser.pulse_width_ns},
                              {"source", std::string(to_string(pen.laser.source))},
                              {"passes", pen.passes},
                              {"pulse_spacing_um", spacing_um}, {"pulse_overlap_fraction", overlap}});
  }
  out["planned_time_s"] = total_s;
  if (!a.preview.empty()) {
    // Written whole after every check passed: a refused job leaves no picture.
    write_file_whole(a.preview, next_part_preview(job, fonts, texts, a.preview));
    out["preview_file"] = a.preview;
  }
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
  if (!a.preview.empty()) std::printf("wrote %s\n", a.preview.c_str());
  std::printf("ok\n");
  return 0;
}

// json[KEY] = value for a setting's job-file key; a key with dots ("head.spot_diameter_um")
// goes into the objects it names.
template <class T>
void put(nlohmann::ordered_json& json, const SettingName& name, const T& value) {
  nlohmann::ordered_json* at = &json;
  std::string_view key = name.key;
  for (std::size_t dot = key.find('.'); dot != std::string_view::npos; dot = key.find('.')) {
    at = &(*at)[std::string(key.substr(0, dot))];
    key.remove_prefix(dot + 1);
  }
  (*at)[std::string(key)] = value;
}

nlohmann::ordered_json new_job_json(const NewArgs& a) {
  nlohmann::ordered_json object = nlohmann::ordered_json::object();
  put(object, kObjectName.name, a.object);
  object["kind"] = "text";
  put(object, kTemplate.name, a.text);
  put(object, kObjectPen.name, a.pen);
  const LayoutArgs& l = a.layout;
  // The text's layout: the font, height and base point always, the rest where not the default.
  put(object, kFont.name, l.font);
  put(object, kHeight.name, l.height_mm);
  const auto unless_default = [&](const Quantity& s, double v) {
    if (v != s.fallback()) put(object, s.name, v);
  };
  unless_default(kWidthFactor, l.width_factor);
  unless_default(kGap, l.gap_mm);
  unless_default(kLineSpacing, l.line_spacing);
  if (l.align != kAlign.value) put(object, kAlign.name, l.align);
  put(object, kX.name, l.x_mm);
  put(object, kY.name, l.y_mm);
  unless_default(kAngle, l.angle_deg);
  unless_default(kItalic, l.italic_deg);
  if (l.mirror) put(object, kMirror.name, true);
  if (l.replace_missing) put(object, kReplaceMissing.name, true);
  if (!l.circle.empty()) {
    const CircleFit c = *to_layout_options(l).circle;
    put(object, kCircleX.name, c.center.x());
    put(object, kCircleY.name, c.center.y());
    put(object, kCircleRadius.name, c.radius_mm);
    put(object, kInside.name, c.inside);
    if (c.start_angle_deg) put(object, kStartAngle.name, *c.start_angle_deg);
  }

  nlohmann::ordered_json pen = nlohmann::ordered_json::object();
  put(pen, kCorner.name, a.corner);
  // auto: run_new writes the speed it picks once the job reads back. A number is checked within
  // the head's limit as the job file's reader checks it (an unknown head is refused there).
  const std::optional<HeadModel> head = find_head(a.head);
  const Range speeds = head ? head_speed_range(kMarkSpeed, *head) : kMarkSpeed.range();
  put(pen, kMarkSpeed.name, number_or_word(kMarkSpeed, a.speed, kAutoSpeed, speeds).value_or(kMarkSpeed.fallback()));
  put(pen, kPower.name, a.laser.power_pct);
  put(pen, kFrequency.name, a.laser.frequency_khz);
  put(pen, kPulseWidth.name, a.laser.pulse_width_ns);
  put(pen, kLaserSource.name, a.source);
  put(pen, kPasses.name, a.passes);
  if (a.jump_speed_mm_s) put(pen, kJumpSpeed.name, *a.jump_speed_mm_s);
  if (a.tick_us) put(pen, kTick.name, *a.tick_us);

  nlohmann::ordered_json job = {{"format", kJobFormat}, {"name", std::filesystem::path(a.output).stem().string()}};
  put(job, kDevice.name, a.device);
  job[std::string(kHead.name.key)] = {{"model", a.head}};  // the head's object form, which holds its spot too
  put(job, kSpot.name, a.spot_um);
  put(job, kField.name, l.field_mm);
  put(job, kTimeZone.name, a.time_zone);
  if (!a.shifts.empty()) {
    nlohmann::ordered_json shifts = nlohmann::ordered_json::array();
    std::size_t pos = 0;
    while (pos <= a.shifts.size()) {
      const std::size_t end = std::min(a.shifts.find(',', pos), a.shifts.size());
      const std::string item = a.shifts.substr(pos, end - pos);
      const std::size_t eq = item.find('=');
      if (eq == std::string::npos)
        throw InputError(std::string(kShifts.name.flag) + " '" + a.shifts +
                         "': expected CODE=HH:MM,… e.g. A=06:00,B=14:00,C=22:00");
      shifts.push_back({{"code", item.substr(0, eq)}, {"start", item.substr(eq + 1)}});
      pos = end + 1;
    }
    put(job, kShifts.name, shifts);
  }
  const auto vars = parse_sets(a.vars);
  if (!vars.empty()) put(job, kVariables.name, nlohmann::ordered_json(vars));
  nlohmann::ordered_json counters = nlohmann::ordered_json::object();
  for (const std::string& name : TextTemplate::parse(a.text, std::string(kTemplate.name.flag)).counters()) {
    nlohmann::ordered_json c = nlohmann::ordered_json::object();
    put(c, kCounterStart.name, a.start);
    put(c, kCounterStep.name, a.step);
    put(c, kCounterWidth.name, a.width);
    put(c, kPadding.name, a.padding);
    put(c, kAlphabet.name, a.alphabet);
    put(c, kAtLimit.name, a.at_limit);
    put(c, kMarksPerSerial.name, a.marks_per_serial);
    put(c, kReset.name, a.reset);
    if (a.limit) put(c, kCounterLimit.name, *a.limit);
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
  if (a.speed == kAutoSpeed) put(j["pens"][a.pen], kMarkSpeed.name, auto_pen_speed(j, a.output));
  const std::string text = j.dump(2) + "\n";
  // What we write must read back (the same checks as any job file) and its first part must be
  // markable, as `job check` judges it (in the field, planned, objects apart).
  const JobFile job = parse_job(text, a.output);
  const JobFonts fonts(job);
  try {
    compile_part(job, fonts, first_part_texts(job, job.variables, SystemClock().now()));
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + " (nothing written)");
  }
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
        add_setting(*c, kSet, check->sets);
        c->add_flag("--json", check->json, "print one JSON object");
        c->add_option("--preview", check->preview,
                      "write the next part's picture (.png or .svg): the store's next values, nothing consumed");
        add_store_options(*c, check->store, false);
        auto* n = job->add_subcommand("new", "write a job file from command-line options");
        NewArgs& a = *created;
        n->add_option("-o,--output", a.output, "job file to write")->required();
        add_setting(*n, kTemplate, a.text)->required();
        add_setting(*n, kObjectName, a.object);
        add_layout_options(*n, a.layout);
        add_setting(*n, kHead, a.head);
        add_setting(*n, kSpot, a.spot_um);
        add_setting(*n, kObjectPen, a.pen);
        add_setting(*n, kCorner, a.corner);
        add_setting(*n, kMarkSpeed, a.speed, kAutoSpeed,
                    std::string(kAutoSpeedHelp) + " for the first part's text, written into the pen");
        // Checked against the head when the written job reads back (as any job file's pen).
        add_head_limited_setting(*n, kJumpSpeed, a.jump_speed_mm_s);
        add_head_limited_setting(*n, kTick, a.tick_us);
        add_laser_options(*n, a.laser);
        add_setting(*n, kLaserSource, a.source);
        add_setting(*n, kPasses, a.passes);
        for (const auto& [setting, value] : {std::pair{&kCounterStart, &a.start}, {&kCounterStep, &a.step},
                                             {&kMarksPerSerial, &a.marks_per_serial}})
          add_setting(*n, *setting, *value)->group("Counters (every counter of the text)");
        for (const auto& [setting, value] : {std::pair{&kAtLimit, &a.at_limit}, {&kAlphabet, &a.alphabet},
                                             {&kPadding, &a.padding}, {&kReset, &a.reset}})
          add_setting(*n, *setting, *value)->group("Counters (every counter of the text)");
        add_setting(*n, kCounterWidth, a.width)->group("Counters (every counter of the text)");
        add_setting(*n, kCounterLimit, a.limit)->group("Counters (every counter of the text)");
        add_setting(*n, kDevice, a.device);
        add_setting(*n, kTimeZone, a.time_zone);
        add_setting(*n, kShifts, a.shifts);
        add_setting(*n, kVariables, a.vars);
        n->add_flag("--force", a.force, "replace an existing file");
        *subs = {c, n};
        return job;
      },
      [=] { return subs->first->parsed() ? run_check(*check) : run_new(*created); });
}

}  // namespace mark::cli
