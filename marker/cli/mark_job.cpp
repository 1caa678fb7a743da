#include "marker/cli/mark_job.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "base/error.hpp"
#include "driver/sim/quality_class.hpp"
#include "marker/cli/device_factory.hpp"
#include "marker/cli/inject_option.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/cli/production_options.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/output/output_file.hpp"
#include "marker/preview/mark_preview.hpp"
#include "marker/preview/sim_outputs.hpp"
#include "driver/sim/grey_png.hpp"
#include "marker/production/part_files.hpp"
#include "marker/production/part_picture.hpp"
#include "marker/production/part_json.hpp"
#include "marker/production/part_run.hpp"
#include "marker/store/open_store.hpp"
#include "marker/store/store_location.hpp"

namespace mark::cli {
namespace {


std::string serials_text(const std::map<std::string, std::int64_t>& serials) {
  std::string s;
  for (const auto& [name, value] : serials)
    s.append(s.empty() ? "" : " ").append(name).append("=").append(std::to_string(value));
  return s;
}

void print_part(const PartResult& p, long long index, long long count, const std::string& files) {
  std::string text = p.text();
  for (char& c : text)
    if (c == '\n') c = '|';
  std::printf("part %lld/%lld  id %lld  %s%s\"%s\"  %s  %.4f s", index, count,
              static_cast<long long>(p.mark_id),
              p.remark_of ? ("re-mark of " + std::to_string(*p.remark_of) + "  ").c_str() : "",
              p.serials.empty() ? "" : (serials_text(p.serials) + "  ").c_str(), text.c_str(),
              std::string(p.outcome_name()).c_str(), p.mark_time_s);
  if (p.quality)
    std::printf(", quality %s (max deviation %.1f µm, coverage %.2f %%)",
                std::string(to_string(classify(*p.quality))).c_str(), p.quality->max_deviation_um,
                100 * p.quality->coverage);
  if (p.pulses)
    std::printf(", pulses %.1f µm apart (overlap %.0f %%)", p.pulses->spacing_max_um,
                100 * p.pulses->overlap());
  std::printf("%s\n", files.c_str());
  std::fflush(stdout);
}

// Ctrl-C, an injected abort or a fault: where the part stopped, on one line (stderr).
void print_stop(const PartResult& p, long long index) {
  const bool interrupted = p.outcome == JobOutcome::aborted && interrupt_flag().requested();
  std::fprintf(stderr, "marker: part %lld (id %lld) %s: %s%s\n", index,
               static_cast<long long>(p.mark_id),
               interrupted ? "interrupted" : std::string(p.outcome_name()).c_str(),
               p.message.c_str(),
               p.serials.empty() || p.remark_of
                   ? ""
                   : ("; its numbers are void (" + serials_text(p.serials) + ")").c_str());
}

}  // namespace

void start_station(SerialStore& store, const MarkContext& context, const JobFile& job, const MarkJobArgs& a) {
  const StationStart started = store.start_station(context);
  const auto ids = [](const std::vector<std::int64_t>& list) {
    std::string s;
    for (std::int64_t id : list) s.append(s.empty() ? "" : ", ").append(std::to_string(id));
    return s;
  };
  if (!started.replayed.empty())
    std::fprintf(stderr, "marker: station %s: %zu outcome(s) the store had not taken were in the outcome journal "
                         "(id %s): recorded now\n",
                 context.station.c_str(), started.replayed.size(), ids(started.replayed).c_str());
  if (!started.closed.empty())
    std::fprintf(stderr,
                 "marker: station %s: %zu part(s) a previous run left without an outcome (id %s) "
                 "recorded aborted; their numbers are void\n",
                 context.station.c_str(), started.closed.size(), ids(started.closed).c_str());
  for (const std::string& n : started.notes) std::fprintf(stderr, "marker: warning: %s\n", n.c_str());
  if (a.remark) return;
  if (a.create_counters) {
    for (const std::string& name : store.create_missing(job.used_counters(), job.shifts, context))
      std::fprintf(stderr, "marker: created counter %s in the store (next value %lld)\n", name.c_str(),
                   static_cast<long long>(job.counters.at(name).start));
    return;
  }
  for (const auto& [name, spec] : job.used_counters()) {
    if (store.status(name, nullptr, job.shifts, context.now).known) continue;
    std::string msg = a.job + ": " + counter_not_in_store(a.job, name, spec, store.describe());
    const std::string old = job_side_store_path(a.job);
    if (a.store.store.empty() && std::filesystem::exists(old))
      msg += "; the job's store from before the station store is " + old + ": mark with --store " + old +
             " or move it (docs/store.md)";
    throw InputError(msg);
  }
}

std::string counter_not_in_store(const std::string& job_path, const std::string& name, const CounterSpec& spec,
                                 const std::string& store) {
  return "counter \"" + name + "\" is not in the serial store " + store +
         ": create it with `marker serial create " + name + " --job " + job_path + "` (starts at " +
         std::to_string(spec.start) + ", or --start N) or mark with --create-counters";
}

namespace {

// The part's outcome did not reach the store: where it is, on one line (stderr).
void print_record(const PartResult& p, long long index) {
  if (p.recorded.stored) return;
  if (p.recorded.journaled)
    std::fprintf(stderr, "marker: part %lld (id %lld): outcome %s kept in the outcome journal %s; the store did not "
                         "take it (%s): it is recorded at the station's next start\n",
                 index, static_cast<long long>(p.mark_id), std::string(p.outcome_name()).c_str(),
                 p.recorded.journal.c_str(), p.recorded.error.c_str());
  else
    std::fprintf(stderr, "marker: part %lld (id %lld): outcome %s NOT recorded: %s\n", index,
                 static_cast<long long>(p.mark_id), std::string(p.outcome_name()).c_str(),
                 p.record_error.c_str());
}

// The run's --preview / --dose-png / --trace: checked before anything is marked, written per part.
struct PartOutputs {
  std::vector<std::pair<PartFile, std::string>> files;  // with the JSON key naming the written file
  PartLookSpec look;
  bool any() const { return !files.empty(); }
  bool traced() const {
    for (const auto& f : files)
      if (f.first.option == "--trace") return true;
    return false;
  }
};

PartOutputs part_outputs(const MarkJobArgs& a, const JobFile& job, const JobFonts& fonts) {
  PartOutputs out;
  check_standard_output({{"--preview", &a.preview}, {"--dose-png", &a.dose_png}, {"--trace", &a.trace}}, a.json);
  const auto take = [&](const char* option, const std::string& pattern, const char* key,
                        std::initializer_list<std::string_view> extensions) {
    if (pattern.empty()) return;
    PartFile f{option, pattern};
    check_part_file(f, job, a.count);
    // The first part's name stands for every part's: the same folder and extension.
    std::map<std::string, std::int64_t> starts;
    for (const auto& [name, spec] : job.used_counters()) starts[name] = spec.start;
    check_output_path(option, part_file_name(f, job, 1, starts), extensions);
    out.files.emplace_back(std::move(f), key);
  };
  take("--preview", a.preview, "preview_file", {".svg", ".png"});
  take("--dose-png", a.dose_png, "dose_png_file", {".png"});
  take("--trace", a.trace, "trace_file", {});
  if (out.any()) out.look = part_look(job, fonts);
  return out;
}

// The part's files, after its outcome is recorded. Returns what the part's line adds ("; wrote …"
// or why a file was not written) and sets `failed` when one could not be.
std::string write_part_outputs(const PartOutputs& out, const PartPicture& picture, const JobFile& job,
                               const PartResult& p, nlohmann::json* line, bool& failed) {
  std::string said;
  for (const auto& [file, key] : out.files) {
    const std::string path = part_file_name(file, job, p.mark_id, p.serials);
    try {
      if (file.option == "--preview") {
        write_mark_preview(picture.plan(), picture.dose(), path);
      } else if (file.option == "--dose-png") {
        const GreyImage image = dose_part_picture(picture.dose(), out.look.response, out.look.look, out.look.dark_part);
        write_file_whole(path, encode_grey_png(image));
        if (line) {
          // Where the picture lies on the field, so a script can lay the objects' boxes on it.
          (*line)["dose_px_um"] = 1e6 / pixels_per_metre(image.pixel_mm);
          (*line)["dose_x0_mm"] = image.x0_mm;
          (*line)["dose_top_mm"] = image.top_mm;
        }
      } else {
        write_trace_csv(picture.trace(), path);
      }
      said += "; wrote " + path;
      if (line) (*line)[key] = path;
    } catch (const std::exception& e) {
      failed = true;
      said += "; " + file.option + " NOT written: " + e.what();
      if (line) (*line)["file_errors"].push_back(file.option + ": " + e.what());
    }
  }
  return said;
}

}  // namespace

int run_mark_job(const MarkJobArgs& a) {
  // The option's validator checks this on the command line; callers from code get the same words.
  if (!kPartCount.range.contains(a.count))
    throw InputError(std::string(kPartCount.name.flag) + ": " + std::to_string(a.count) + " is outside the range " +
                     kPartCount.range.text());
  if (a.remark && (a.count != 1 || !a.sets.empty()))
    throw InputError("--remark " + std::to_string(*a.remark) +
                     " marks one part again with its recorded texts: --count and --set do not apply");
  if (!a.reason.empty() && !a.remark) throw InputError("--reason applies to a re-mark: give --remark ID");
  if (a.allow_changed_job && !a.remark)
    throw InputError("--allow-changed-job does not apply: only a re-mark reads it (give --remark ID)");
  std::string bytes;
  const JobFile job = read_job_file(a.job, &bytes);
  const auto variables = job_variables(job, parse_sets(a.sets));
  for (const std::string& v : job.required_variables())
    if (!a.remark && !variables.count(v))
      throw InputError(a.job + ": {var:" + v + "} has no default in the job: give --set " + v + "=VALUE");
  std::vector<std::string> warnings;
  const JobFonts fonts(job, &warnings);
  for (const std::string& w : warnings) std::cerr << "marker: warning: " << w << "\n";
  const InjectArg inject = a.inject.empty() ? InjectArg{} : parse_inject(a.inject);
  const PartOutputs outputs = part_outputs(a, job, fonts);

  // The store before the device: a store that refuses (damaged, a counter it does not know)
  // is reported before anything is switched on.
  StoreSettings settings;
  settings.journal_dir = default_journal_dir();
  settings.interrupts = interrupt_count;
  settings.fault = inject.store;
  auto store = open_production_store(a.store, a.remark ? StoreAccess::existing : StoreAccess::create,
                                     std::move(settings), inject.store.has_value());
  MarkContext context = mark_context(a.station, a.job, bytes);
  context.now = SystemClock().now();
  start_station(*store, context, job, a);

  SimSettings sim;
  sim.fault_at = inject.device_fault_at;
  sim.virtual_time = a.virtual_time;
  sim.trace = outputs.traced();
  const OpenedDevice opened = open_device(
      a.device.empty() ? job.device : a.device, object_spec(job, job.objects.front(), "", fonts), sim);
  Device& device = *opened.device;
  if (outputs.any() && !opened.simulator)
    throw InputError("--preview, --dose-png and --trace need a simulated scanner (--device sim or lmc-emulated); "
                     "nothing was marked");
  PartRunner runner(job, fonts, variables, device, *store, context);

  PartOptions options;
  options.job.evaluator = opened.simulator.get();
  options.job.virtual_time = a.virtual_time;
  options.job.stop = &interrupt_flag();
  options.job.inject = inject.drain;
  options.remark_reason = a.reason;
  options.allow_changed_job = a.allow_changed_job;
  // Every object's dose and trace, read off the scanner before the next object clears them.
  std::optional<PartPicture> picture;
  if (outputs.any())
    options.object_marked = [&](std::size_t, const JobResult& marked) {
      const SimScanner& scanner = opened.simulator->scanner();
      picture->add(marked.job.plan, scanner.picture_dose(), scanner.trace());
    };
  bool warned_dots = false, warned_poor = false;
  for (long long i = 1; i <= a.count; ++i) {
    if (interrupt_flag().requested()) {
      std::fprintf(stderr, "marker: interrupted after part %lld of %lld; no further part started\n",
                   i - 1, a.count);
      return kExitInterrupted;
    }
    if (outputs.any()) picture.emplace(opened.simulator->scanner().dose().pixel_mm());
    const PartResult p = a.remark ? runner.remark(*a.remark, SystemClock().now(), options)
                                  : runner.mark_next(SystemClock().now(), options);
    nlohmann::json line;
    if (a.json) {
      line = part_line(p);
      line["part"] = i;
    }
    // The files after the outcome is recorded (mark_next has): a picture never delays a serial's
    // commit. A part stopped by Ctrl-C leaves none (as `mark`); a failed one shows how far it got.
    bool files_failed = false;
    std::string files;
    if (outputs.any() && picture->objects() > 0 && !interrupt_flag().requested())
      files = write_part_outputs(outputs, *picture, job, p, a.json ? &line : nullptr, files_failed);
    if (a.json)
      std::cout << line.dump() << std::endl;  // flushed: a reader follows the run part by part
    else
      print_part(p, i, a.count, files);
    print_record(p, i);
    if (!p.note.empty()) std::fprintf(stderr, "marker: warning: part %lld: %s\n", i, p.note.c_str());
    if (!p.good()) {
      print_stop(p, i);
      // A rejected part exits 2, as `marker code` does for a code that does not read.
      return p.rejected ? kExitRejected : p.outcome == JobOutcome::aborted ? kExitInterrupted : 1;
    }
    if (!p.recorded.stored && !p.recorded.journaled) return 1;  // not even the journal took it
    if (files_failed) {
      std::fprintf(stderr, "marker: part %lld (id %lld) is %s as recorded; a file of it was not written: "
                           "no further part started\n",
                   i, static_cast<long long>(p.mark_id), std::string(p.outcome_name()).c_str());
      return 1;
    }
    if (p.pulses && p.pulses->separate_dots() && !warned_dots) {
      warned_dots = true;
      std::fprintf(stderr,
                   "marker: warning: pulses land %.1f µm apart on a %.0f µm spot: lit strokes show "
                   "as separate dots; lower the pen's speed or raise its frequency\n",
                   p.pulses->spacing_max_um, p.pulses->spot_diameter_um);
    }
    if (p.quality && classify(*p.quality) == QualityClass::poor && !warned_poor) {
      warned_poor = true;
      std::fprintf(stderr, "marker: warning: poor mark predicted (%s): lower the pen's speed\n",
                   quality_figures(*p.quality).c_str());
    }
  }
  return 0;
}

}  // namespace mark::cli
