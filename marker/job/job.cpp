#include "marker/job/job.hpp"

#include <algorithm>

#include "fonts/error.hpp"
#include "marker/job/device_program.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/job/job_run.hpp"
#include "marker/locus/locus_generator.hpp"

namespace mark {

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

CompiledJob compile_job(const JobSpec& spec, DeviceLevel level) {
  if (spec.text.empty()) throw InputError("the text to mark is empty");
  if (!spec.font) throw InputError("no font given for the text to mark");
  check_pen(spec.pen, spec.head);
  CompiledJob job;
  job.figure = layout_text(spec.text, *spec.font, spec.layout);
  // The letters themselves first, so the message says which part leaves the field.
  if (!job.figure.bounds().empty())
    require_inside(job.figure.bounds(), Field{spec.head.field_mm}, "the text layout");
  job.plan = level == DeviceLevel::commands ? plan_for_device(job.figure, spec.pen, spec.order)
                                            : plan_figure(job.figure, spec.pen, spec.order);
  check_plan(job.plan, spec.head);
  job.laser_on_ticks = spec.pen.ticks(spec.pen.laser_on_delay_s);
  job.laser_off_ticks = spec.pen.ticks(spec.pen.laser_off_delay_s);
  return job;
}

JobResult run_job(const JobSpec& spec, const JobOptions& options, Device& device) {
  JobResult result;
  const DeviceDescription desc = device.describe();
  const JobClock::time_point t0 = JobClock::now();
  result.job = compile_job(spec, desc.level);
  const double compiled_s = seconds_since(t0);
  if (spec.head.field_mm > desc.field_mm * (1 + 1e-12))
    throw InputError("the job's field (" + std::to_string(spec.head.field_mm) +
                     " mm) is larger than the field of device " + desc.name + " (" +
                     std::to_string(desc.field_mm) + " mm)");
  // A station reuses its device: one left done / aborted / failed by the last job is re-armed.
  const DeviceState state = device.status().state;
  if (state != DeviceState::idle && state != DeviceState::running) device.reset();

  if (desc.level == DeviceLevel::samples) {
    auto* samples = dynamic_cast<SampleDevice<ScanSample>*>(&device);
    if (!samples)
      throw DeviceFaultError({FaultCategory::device,
                              desc.name + " takes samples of another kind than scanner samples", 0});
    device.begin_job(job_header(spec, result.job, desc));
    run_samples(spec, options, *samples, compiled_s, result);
  } else {
    auto* commands = dynamic_cast<CommandDevice*>(&device);
    if (!commands)
      throw DeviceFaultError({FaultCategory::device, desc.name + " takes no device commands", 0});
    run_commands(spec, options, *commands, result);
    result.compile_time_s = compiled_s;
  }
  result.wall_time_s = seconds_since(t0);
  result.glyphs = result.job.figure.glyphs.size();
  result.strokes = result.job.plan.strokes;
  result.jump_length_mm = result.job.plan.jump_length_mm;
  if (result.outcome == JobOutcome::done) result.ink_marked = 1;
  return result;
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

SimScannerOptions simulator_options(const JobSpec& spec) {
  SimScannerOptions o;
  o.head = spec.head;
  o.tick_s = spec.pen.tick_s;
  o.record_lit_paths = true;
  return o;
}

JobResult run_job_simulated(const JobSpec& spec, const JobOptions& options, SimScanner& scanner,
                            const QualityReference* reference) {
  JobResult result = run_job(spec, options, scanner);
  result.quality = reference ? reference->evaluate(scanner.lit_paths(), scanner.dose())
                             : evaluate_quality(intended_polylines(result.job.figure),
                                                scanner.lit_paths(), scanner.dose());
  return result;
}

}  // namespace mark
