#include "marker/production/part_run.hpp"

#include <algorithm>
#include <cstdio>

#include "base/error.hpp"
#include "driver/sim/quality_class.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/production/object_clearance.hpp"
#include "marker/production/part_json.hpp"
#include "marker/production/part_verdict.hpp"
#include "marker/store/utc_time.hpp"

namespace mark {
namespace {

std::string in_quotes(const std::string& s) { return "\"" + s + "\""; }

}  // namespace

std::string PartResult::text() const {
  std::string t;
  for (const ObjectText& o : texts) t.append(t.empty() ? "" : "\n").append(o.text);
  return t;
}

std::string_view PartResult::outcome_name() const {
  return rejected ? to_string(Outcome::rejected) : to_string(outcome);
}

PartRunner::PartRunner(const JobFile& job, const JobFonts& fonts,
                       std::map<std::string, std::string> variables, Device& device,
                       SerialStore& store, MarkContext context)
    : job_(job),
      variables_(std::move(variables)),
      device_(device),
      store_(store),
      context_(std::move(context)),
      counters_(job.used_counters()) {
  const DeviceDescription desc = device.describe();
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    const JobObject& o = job.objects[i];
    JobSpec spec = object_spec(job, o, "", fonts);
    check_field(spec.head, desc);  // before any serial is taken, not as a part that could not start
    // A sample-level device runs on one sample clock: every pen's tick must be it.
    if (desc.level == DeviceLevel::samples && std::abs(spec.pen.tick_s - desc.tick_s) > 1e-12) {
      char msg[240];
      std::snprintf(msg, sizeof msg,
                    "pen \"%s\" ticks every %g µs, the device %s every %g µs: a sample-level "
                    "device runs on one clock, give every pen its tick_us",
                    o.pen.c_str(), spec.pen.tick_s * 1e6, desc.name.c_str(), desc.tick_s * 1e6);
      throw InputError(object_place(job, i) + msg);
    }
    predictors_.emplace_back();
    if (o.require.any() && desc.level != DeviceLevel::samples)
      predictors_.back().emplace(spec, DeviceLevel::samples, o.code() && o.code()->escapes);
    compilers_.emplace_back(std::move(spec), desc.level, o.code() && o.code()->escapes);
  }
  if (job.data) data_ = load_data_list(job);
  mirrors_ = device_position();
}

std::vector<CompiledJob> PartRunner::compile(const std::vector<ObjectText>& texts) {
  std::vector<CompiledJob> compiled;
  compiled.reserve(texts.size());
  Point home = mirrors_;
  for (std::size_t i = 0; i < compilers_.size(); ++i) {
    try {
      compiled.push_back(compilers_[i].compile(texts.at(i).text, home));
      if (job_.objects[i].require.any()) refuse_predicted_shortfall(i, texts.at(i).text, compiled.back(), home);
    } catch (const InputError& e) {
      throw InputError(object_place(job_, i) + e.what());
    }
    if (!compiled.back().plan.commands.empty()) home = compiled.back().plan.commands.back().end();
  }
  check_objects_apart(job_, compiled);
  return compiled;
}

void PartRunner::refuse_predicted_shortfall(std::size_t object, const std::string& text,
                                            const CompiledJob& compiled, const Point& home) {
  std::optional<JobCompiler>& predictor = predictors_[object];
  const JobSpec spec = marked_spec(object, text);
  const auto why = predictor ? predicted_shortfall(spec, predictor->compile(text, home), job_.objects[object].require)
                             : predicted_shortfall(spec, compiled, job_.objects[object].require);
  if (why) throw InputError("the simulator predicts " + *why + " (\"require\"); nothing was fired");
}

JobSpec PartRunner::marked_spec(std::size_t i, const std::string& text) const {
  JobSpec spec = compilers_[i].spec();
  const JobObject& object = job_.objects[i];
  set_marked_text(spec, text, object.code() && object.code()->escapes);
  return spec;
}

std::vector<ObjectText> PartRunner::next_texts(SysTime now, const std::map<std::string, std::int64_t>& serials) {
  std::map<std::string, std::string> columns;
  if (data_) {
    const auto row = store_.next_data_row(data_pick());
    if (!row)
      throw InputError("data list " + job_.data->file + ": every row was taken by an earlier part (" +
                       std::to_string(data_->size()) + " rows in the file): the next part would be refused");
    columns = data_->values(*row);
  }
  return render_objects(job_, variables_, now, serials, &columns);
}

DataPick PartRunner::data_pick() const {
  DataPick pick;
  if (data_) pick = {&*data_, job_.data->file, next_row_};
  return pick;
}

PartResult PartRunner::mark_next(SysTime now, const PartOptions& options) {
  using Steady = std::chrono::steady_clock;
  PartTimes times;
  times.started = Steady::now();
  context_.now = now;
  std::vector<CompiledJob> compiled;
  if (options.phase) options.phase(PartPhase::allocating, {});
  // Rendering, layout, planning and every refusal happen inside the transaction: a refused
  // part consumes nothing.
  const Allocation a = store_.allocate(counters_, job_.shifts, context_, data_pick(), [&](const PartValues& v) {
    std::map<std::string, std::string> columns;
    if (v.data_row) columns = data_->values(*v.data_row);
    const auto t0 = Steady::now();
    std::vector<ObjectText> texts = render_objects(job_, variables_, v.now, v.serials, &columns);
    compiled = compile(texts);
    times.compile_s = std::chrono::duration<double>(Steady::now() - t0).count();
    return texts;
  });
  times.committed = Steady::now();
  if (a.data_row) next_row_ = *a.data_row + 1;
  PartResult part;
  part.times = times;
  part.mark_id = a.mark_id;
  part.texts = a.objects;
  part.serials = a.serials;
  if (a.data_row) part.data_row = static_cast<std::int64_t>(*a.data_row) + 1;
  part.note = a.note;
  return run(std::move(part), std::move(compiled), options);
}

PartResult PartRunner::remark(std::int64_t original, SysTime now, const PartOptions& options) {
  context_.now = now;
  if (options.phase) options.phase(PartPhase::allocating, {});
  // Refuses a row of another job, or of this one changed since, unless allowed.
  const Allocation a = store_.remark(original, context_, options.remark_reason, options.allow_changed_job);
  PartResult part;
  part.mark_id = a.mark_id;
  part.remark_of = a.remark_of;
  if (a.data_row) part.data_row = static_cast<std::int64_t>(*a.data_row) + 1;
  part.texts = a.objects;
  part.serials = a.serials;
  std::vector<CompiledJob> compiled;
  try {
    if (a.objects.size() != job_.objects.size())
      throw InputError("--remark " + std::to_string(original) + ": that row has " +
                       std::to_string(a.objects.size()) + " object(s), the job " +
                       std::to_string(job_.objects.size()));
    compiled = compile(a.objects);
  } catch (const InputError& e) {
    // The re-mark's row is written; it is closed as failed, nothing marked.
    part.outcome = JobOutcome::failed;
    part.message = std::string("nothing marked: ") + e.what();
    record(part, options);
    throw;
  }
  return run(std::move(part), std::move(compiled), options);
}

PartResult PartRunner::run(PartResult part, std::vector<CompiledJob> compiled,
                           const PartOptions& options) {
  if (options.phase) options.phase(PartPhase::marking, part.serials);
  part.device = device_.describe().name;
  for (std::size_t i = 0; i < job_.objects.size(); ++i) {
    ObjectRun o;
    o.name = job_.objects[i].name;
    o.pen = job_.objects[i].pen;
    o.text = part.texts.at(i).text;
    part.objects.push_back(std::move(o));
  }
  // Where the mirrors will be after the part, if every object is marked to its end.
  const Point end = compiled.empty() || compiled.back().plan.commands.empty()
                        ? mirrors_
                        : compiled.back().plan.commands.back().end();
  std::vector<JobSpec> specs;  // each object's job with the part's text: marked, then judged
  specs.reserve(part.objects.size());
  std::size_t i = 0;
  try {
    for (; i < part.objects.size(); ++i) {
      ObjectRun& o = part.objects[i];
      const JobSpec& spec = specs.emplace_back(marked_spec(i, o.text));
      o.result = run_compiled_job(spec, std::move(compiled[i]), options.job, device_);
      o.started = true;
      if (options.object_marked) options.object_marked(i, o.result);
      if (o.result.outcome != JobOutcome::done) {
        part.outcome = o.result.outcome;
        part.stopped_object = i;
        break;
      }
    }
  } catch (const std::exception& e) {
    mirrors_ = device_position();
    // The device could not start object i (or refused it): nothing more of this part is
    // marked. The outcome is recorded before the error goes on, so the audit log is complete.
    part.outcome = JobOutcome::failed;
    part.stopped_object = i;
    part.message = "object " + in_quotes(part.objects[i].name) + " could not start: " + e.what();
    summarise(part);
    record(part, options);
    throw;
  }
  mirrors_ = part.outcome == JobOutcome::done ? end : device_position();
  if (part.outcome == JobOutcome::done) {
    std::vector<MarkedObject> marked;
    for (std::size_t k = 0; k < part.objects.size(); ++k)
      marked.push_back({&specs[k], &part.objects[k].result, job_.objects[k].require});
    if (const std::optional<Rejection> r = part_verdict(marked)) {
      part.rejected = true;
      part.stopped_object = r->object;
      part.message = "object " + in_quotes(part.objects[r->object].name) + ": " + r->reason;
    }
  }
  summarise(part);
  record(part, options);
  return part;
}

Point PartRunner::device_position() const {
  const Vec2 at = device_.status().position;
  return Point(at.x, at.y);
}

void PartRunner::record(PartResult& part, const PartOptions& options) {
  if (options.phase) options.phase(PartPhase::recording, part.serials);
  OutcomeRecord record;
  record.time_utc = format_utc(SystemClock().now());
  record.outcome = part.rejected                         ? Outcome::rejected
                   : part.outcome == JobOutcome::done    ? Outcome::done
                   : part.outcome == JobOutcome::aborted ? Outcome::aborted
                                                         : Outcome::failed;
  record.message = part.message;
  record.figures = part_figures(part);
  try {
    // Journal first, then the store: a part marked in full is never logged void for want of a
    // store write (serial_store.hpp).
    part.recorded = store_.record_outcome(part.mark_id, record);
  } catch (const StoreError& e) {
    part.record_error = e.what();  // the caller still reports the part, with this
  }
  if (options.phase) options.phase(PartPhase::finished, part.serials);
}

void PartRunner::summarise(PartResult& part) const {
  for (const ObjectRun& o : part.objects) {
    if (!o.started) continue;
    part.mark_time_s += o.result.mark_time_s;
    part.samples += o.result.samples;
    if (o.result.quality)
      part.quality = part.quality ? worse_of(*part.quality, *o.result.quality) : *o.result.quality;
    if (o.result.pulses && (!part.pulses || o.result.pulses->spacing_max_um > part.pulses->spacing_max_um))
      part.pulses = o.result.pulses;
  }
  if (!part.stopped_object || !part.message.empty()) return;
  // Which object stopped where, what was marked before it and what was not.
  const std::size_t k = *part.stopped_object;
  const ObjectRun& o = part.objects[k];
  const JobResult& r = o.result;
  const bool samples = device_.describe().level == DeviceLevel::samples;
  char where[200];
  std::snprintf(where, sizeof where, " at %s %llu: %.1f %% of its ink marked, laser off",
                samples ? "sample" : "device command", static_cast<unsigned long long>(r.stopped_at),
                100 * r.ink_marked);
  std::string m = "object " + in_quotes(o.name) + " (" + std::to_string(k + 1) + " of " +
                  std::to_string(part.objects.size()) + ") " + std::string(to_string(r.outcome));
  if (r.fault) m += " (" + std::string(to_string(r.fault->category)) + ": " + r.fault->message + ")";
  m += where;
  std::string done, rest;
  for (std::size_t i = 0; i < part.objects.size(); ++i) {
    if (i < k) done += (done.empty() ? "" : ", ") + in_quotes(part.objects[i].name);
    if (i > k) rest += (rest.empty() ? "" : ", ") + in_quotes(part.objects[i].name);
  }
  if (!done.empty()) m += "; marked before it: " + done;
  if (!rest.empty()) m += "; not marked: " + rest;
  part.message = m;
}

}  // namespace mark
