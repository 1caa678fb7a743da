#include "marker/job/job.hpp"

#include <algorithm>

#include "fonts/error.hpp"
#include "marker/job/device_program.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job_compiler.hpp"
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
  check_spec(spec, spec.text);
  CompiledJob job;
  job.level = level;
  job.figure = layout_text(spec.text, *spec.font, spec.layout);
  check_layout(job.figure, spec);
  job.plan = level == DeviceLevel::commands ? plan_for_device(job.figure, spec.pen, spec.order)
                                            : plan_figure(job.figure, spec.pen, spec.order);
  complete_plan(job, spec);
  return job;
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
  if (const auto* sim = dynamic_cast<const SimScanner*>(&device)) result.pulses = sim->pulses();
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
  return run_on_device(spec, std::move(job), 0, JobClock::now(), options, device);
}

JobHeader job_header(const JobSpec& spec, const CompiledJob& job, const DeviceDescription& device) {
  JobHeader h;
  h.name = spec.text;
  h.field_mm = spec.head.field_mm;
  h.pens.push_back(device_pen(job.plan.pen, spec.laser, device.level));
  if (device.level == DeviceLevel::samples) {
    // The locus, the delay line's tail (at most the longer delay and its off sample) and the
    // drain's closing safe sample.
    h.expected_samples = LocusGenerator::count_samples(job.plan.commands, spec.pen.tick_s) +
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
  result.quality = simulated_quality(result, scanner, reference);
  return result;
}

Quality simulated_quality(const JobResult& result, const SimScanner& scanner,
                          const QualityReference* reference) {
  return reference ? reference->evaluate(scanner.lit_paths(), scanner.dose())
                   : evaluate_quality(intended_polylines(result.job.figure), scanner.lit_paths(),
                                      scanner.dose());
}

}  // namespace mark
