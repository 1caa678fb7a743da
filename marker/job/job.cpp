#include "marker/job/job.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "fonts/stroke_font.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/fill/fill.hpp"
#include "marker/job/device_program.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/job/job_compiler.hpp"
#include "marker/job/job_run.hpp"
#include "marker/job/mark_evaluator.hpp"
#include "marker/locus/locus_generator.hpp"

namespace mark {

JobOutcome job_outcome(DeviceState ending) {
  switch (ending) {
    case DeviceState::done: return JobOutcome::done;
    case DeviceState::failed: return JobOutcome::failed;
    default: return JobOutcome::aborted;
  }
}

std::string_view to_string(JobOutcome outcome) {
  switch (outcome) {
    case JobOutcome::done: return "done";
    case JobOutcome::aborted: return "aborted";
    case JobOutcome::failed: return "failed";
  }
  return "?";
}

double seconds_since(JobClock::time_point t0) {
  return std::chrono::duration<double>(JobClock::now() - t0).count();
}

void set_marked_text(JobSpec& spec, std::string_view text, bool code_escapes) {
  if (spec.codes.empty())
    spec.text = text;
  else
    spec.codes.front().spec.data = code_escapes ? unescape_code_data(text) : std::string(text);
}

Figure job_figure(const JobSpec& spec, std::vector<PlacedCode>* codes, std::string_view field_remedy) {
  const Field field{spec.head.field_mm};
  Figure figure;
  if (!spec.text.empty()) {
    if (!spec.font) throw InputError("no font given for the text to mark");
    figure = layout_text(spec.text, *spec.font, spec.layout);
    check_layout(figure, spec, field_remedy);  // the letters before their fill, so the message names them
    if (spec.fill) figure = fill_figure(figure, *spec.fill);
  }
  std::vector<PlacedCode> placed;
  for (std::size_t k = 0; k < spec.codes.size(); ++k) {
    PlacedCode code = place_encoded(spec.codes[k]);
    const std::string name = "code " + std::to_string(k + 1);
    // The quiet zone belongs to the code: it must fit in the field, and nothing else may be
    // marked in it (a reader needs it bare), nor may the code be marked over an earlier one.
    require_inside(code.bounds, field, name + " with its quiet zone");
    for (const PlacedGlyph& g : figure.glyphs)
      if (const auto p = code.first_intrusion(g.elements))
        throw InputError(name + ": its quiet zone is marked by " +
                         (g.code_point ? "the text (glyph " + describe_code_point(g.code_point) + ")"
                                       : std::string("an earlier code")) +
                         " at (" + std::to_string(p->x()) + ", " + std::to_string(p->y()) +
                         ") mm; move the code or the text apart");
    for (std::size_t e = 0; e < placed.size(); ++e)
      if (placed[e].first_intrusion(code.elements))
        throw InputError(name + " is marked in the quiet zone of code " + std::to_string(e + 1) +
                         "; move them apart");
    for (PlacedGlyph& g : code_figure(code).glyphs) figure.glyphs.push_back(std::move(g));
    placed.push_back(std::move(code));
  }
  if (codes) *codes = std::move(placed);
  return figure;
}

CompiledJob lay_out_job(const JobSpec& spec, std::string_view field_remedy) {
  check_text(spec, spec.text);
  CompiledJob job;
  job.figure = job_figure(spec, &job.codes, field_remedy);
  return job;
}

CompiledJob plan_job(CompiledJob job, const JobSpec& spec, DeviceLevel level, const Point& home) {
  check_pen(spec.pen, spec.head);
  job.level = level;
  job.plan = level == DeviceLevel::commands ? plan_for_device(job.figure, spec.pen, spec.order)
                                            : plan_figure(job.figure, spec.pen, spec.order, home);
  complete_plan(job, spec);
  return job;
}

CompiledJob compile_job(const JobSpec& spec, DeviceLevel level, const Point& home) {
  // The pen is known: refuse it before the work of a layout, as a spec's refusals come first.
  check_text(spec, spec.text);
  check_pen(spec.pen, spec.head);
  return plan_job(lay_out_job(spec), spec, level, home);
}

namespace {

// After the compile: the device's own refusals, begin_job, the stream, end_job.
JobResult run_on_device(const JobSpec& spec, CompiledJob job, double compiled_s,
                        JobClock::time_point t0, const JobOptions& options, Device& device) {
  JobResult result;
  const DeviceDescription desc = device.describe();
  const auto kind = [](DeviceLevel l) { return l == DeviceLevel::samples ? "sample-level" : "command-level"; };
  if (job.level != desc.level)
    throw InputError(std::string("the job was compiled for a ") + kind(job.level) + " device; " +
                     desc.name + " is " + kind(desc.level));
  result.job = std::move(job);
  check_field(spec.head, desc);
  // A station reuses its device: one left done / aborted / failed by the last job is re-armed.
  const DeviceState state = device.status().state;
  if (state != DeviceState::idle && state != DeviceState::running) device.reset();

  SampleDevice<ScanSample>* samples = nullptr;
  CommandDevice* commands = nullptr;
  if (desc.level == DeviceLevel::samples) {
    samples = device.as_sample_device<ScanSample>();
    if (!samples)
      throw DeviceFaultError({FaultCategory::device,
                              desc.name + " takes samples of another kind than scanner samples", 0});
  } else {
    commands = device.as_command_device();
    if (!commands)
      throw DeviceFaultError({FaultCategory::device, desc.name + " takes no device commands", 0});
  }
  if (options.evaluator) options.evaluator->begin(spec, result.job);
  try {
    if (samples) {
      run_samples(spec, options, *samples, job_header(spec, result.job, desc), compiled_s, result);
    } else {
      run_commands(spec, options, *commands, result);
      result.compile_time_s = compiled_s;
    }
  } catch (const DeviceStateError& e) {
    // A stop between the re-arm above and begin_job (a station's ABORT from its network thread):
    // the stop flag was raised first, then abort() found the device idle and left it aborted, so
    // begin_job refused. Nothing reached the device: the job ended aborted before its first
    // sample, not failed (the next job re-arms the device).
    const bool stopped_first = options.stop && options.stop->requested();
    if (!stopped_first || e.call() != "begin_job" || e.state() != DeviceState::aborted) throw;
    result.outcome = JobOutcome::aborted;
    result.stopped_at = 0;
    result.ink_marked = 0;
    result.compile_time_s = compiled_s;
  }
  result.wall_time_s = seconds_since(t0);
  result.glyphs = result.job.figure.glyphs.size();
  result.strokes = result.job.plan.strokes;
  result.jump_length_mm = result.job.plan.jump_length_mm;
  if (result.outcome == JobOutcome::done) result.ink_marked = 1;
  if (options.evaluator) options.evaluator->evaluate(spec, result);
  return result;
}

}  // namespace

JobResult run_job(const JobSpec& spec, const JobOptions& options, Device& device) {
  const JobClock::time_point t0 = JobClock::now();
  CompiledJob job = compile_job(spec, device.describe().level);
  return run_on_device(spec, std::move(job), seconds_since(t0), t0, options, device);
}

JobResult run_compiled_job(const JobSpec& spec, CompiledJob job, const JobOptions& options,
                           Device& device) {
  return run_on_device(spec, std::move(job), options.compiled_s, JobClock::now(), options, device);
}

JobHeader job_header(const JobSpec& spec, const CompiledJob& job, const DeviceDescription& device) {
  JobHeader h;
  h.name = spec.text;
  h.field_mm = spec.head.field_mm;
  h.pens.push_back(device_pen(job.plan.pen, spec.laser, device.level));
  if (device.level == DeviceLevel::samples) {
    // The locus, the delay line's tail (at most the longer delay and its off sample) and the
    // drain's closing safe sample.
    h.expected_samples = LocusGenerator::count_samples(job.plan) +
                         std::max(job.laser_on_ticks, job.laser_off_ticks) + 3;
    h.lit_paths = intended_polylines(job.figure, 0.05);
  }
  return h;
}

}  // namespace mark
