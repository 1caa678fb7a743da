#include "marker/cli/serve_source.hpp"

#include <iostream>

#include "base/error.hpp"
#include "marker/cli/inject_option.hpp"
#include "marker/cli/part_preview.hpp"
#include "marker/store/store_location.hpp"

namespace mark::cli {

struct JobSource::Loaded {
  std::string bytes;
  JobFile job;
  std::unique_ptr<JobFonts> fonts;
  std::map<std::string, std::string> sets;  // SET so far (the job's defaults under them)
  MarkContext context;
  std::unique_ptr<PartRunner> runner;
};

JobSource::JobSource(MarkJobArgs args) : args_(std::move(args)) {
  StoreSettings settings;
  settings.journal_dir = default_journal_dir();
  store_ = open_production_store(args_.store, StoreAccess::create, std::move(settings));
  loaded_ = open_job(args_.job, parse_sets(args_.sets));
}

JobSource::~JobSource() {
  loaded_.reset();  // the runner before the device it holds
}

std::unique_ptr<JobSource::Loaded> JobSource::open_job(const std::string& path,
                                                       const std::map<std::string, std::string>& sets) {
  auto l = std::make_unique<Loaded>();
  l->job = read_job_file(path, &l->bytes);
  l->sets = sets;
  const auto variables = job_variables(l->job, sets);
  std::vector<std::string> warnings;
  l->fonts = std::make_unique<JobFonts>(l->job, &warnings);
  for (const std::string& w : warnings) std::cerr << "marker: warning: " << w << "\n";
  l->context = mark_context(args_.station, path, l->bytes);
  l->context.now = SystemClock().now();
  MarkJobArgs a = args_;
  a.job = path;
  start_station(*store_, l->context, l->job, a);
  const std::string spec = args_.device.empty() ? l->job.device : args_.device;
  if (!opened_.device) {
    // --inject as `marker mark --job` takes it (the tests' device fault and drain faults);
    // `marker serve` itself declares no --inject.
    const InjectArg inject = args_.inject.empty() ? InjectArg{} : parse_inject(args_.inject);
    SimSettings sim;
    sim.virtual_time = args_.virtual_time;
    sim.fault_at = inject.device_fault_at;
    options_.job.inject = inject.drain;
    opened_ = open_device(spec, object_spec(l->job, l->job.objects.front(), "", *l->fonts), sim);
    device_spec_ = spec;
    options_.job.evaluator = opened_.simulator.get();
    options_.job.virtual_time = args_.virtual_time;
  } else if (spec != device_spec_) {
    // The device stays open for the station's life (a board's session, the scanner's state).
    throw InputError(path + ": the job names device \"" + spec + "\"; the station has \"" + device_spec_ +
                     "\" open: restart `marker serve` for another device");
  }
  l->runner = std::make_unique<PartRunner>(l->job, *l->fonts, variables, *opened_.device, *store_, l->context);
  return l;
}

PartResult JobSource::mark_next(const StopFlag& stop) {
  for (const std::string& v : loaded_->job.required_variables())
    if (!loaded_->runner->variables().count(v))
      throw InputError(args_.job + ": {var:" + v + "} has no value: SET " + v + " <value> first");
  options_.job.stop = &stop;
  return loaded_->runner->mark_next(SystemClock().now(), options_);
}

void JobSource::abort_device() noexcept { opened_.device->abort(); }

void JobSource::reset_device() { opened_.device->reset(); }

void JobSource::set_variable(const std::string& name, const std::string& value) {
  auto sets = loaded_->sets;
  sets[name] = value;
  loaded_->runner->set_variables(job_variables(loaded_->job, sets));  // throws for a name no template uses
  loaded_->sets = std::move(sets);
}

std::vector<ObjectText> JobSource::preview(std::map<std::string, std::int64_t>* serials) {
  const SysTime now = SystemClock().now();
  const std::map<std::string, std::int64_t> values = next_serials(loaded_->job, *store_, now);
  if (serials) *serials = values;
  return loaded_->runner->next_texts(now, values);
}

std::string JobSource::preview_png() {
  return next_part_preview(loaded_->job, *loaded_->fonts, preview(nullptr), "preview.png");
}

std::optional<std::int64_t> JobSource::next_serial(const std::string& counter) {
  const auto used = loaded_->job.used_counters();
  const auto it = used.find(counter);
  if (it == used.end()) throw InputError("SERIAL " + counter + ": the job uses no counter of that name");
  return store_->status(counter, &it->second, loaded_->job.shifts, SystemClock().now()).next;
}

void JobSource::read_log(const AuditFilter& filter, const std::function<bool(const AuditRow&)>& row) {
  std::lock_guard lock(log_mutex_);
  if (!log_store_) log_store_ = open_production_store(args_.store, StoreAccess::read_only);
  log_store_->read_log(filter, row);
}

void JobSource::load(const std::string& job) {
  auto next = open_job(job, {});  // the old job stays until the new one is ready
  loaded_ = std::move(next);
  args_.job = job;
}

}  // namespace mark::cli
