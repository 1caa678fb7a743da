#include "marker/job/job.hpp"

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

#include "fonts/error.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/locus/locus_generator.hpp"
#include "ringbuffer/drain.hpp"
#include "ringbuffer/laser_delay_line.hpp"
#include "ringbuffer/line_memory.hpp"

namespace mark {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

CompiledJob compile_job(const JobSpec& spec) {
  if (spec.text.empty()) throw InputError("the text to mark is empty");
  if (!spec.font) throw InputError("no font given for the text to mark");
  check_pen(spec.pen, spec.head);
  CompiledJob job;
  job.figure = layout_text(spec.text, *spec.font, spec.layout);
  // The letters themselves first, so the message says which part leaves the field.
  if (!job.figure.bounds().empty())
    require_inside(job.figure.bounds(), Field{spec.head.field_mm}, "the text layout");
  job.plan = plan_figure(job.figure, spec.pen, spec.order);
  check_plan(job.plan, spec.head);
  job.laser_on_ticks = spec.pen.ticks(spec.pen.laser_on_delay_s);
  job.laser_off_ticks = spec.pen.ticks(spec.pen.laser_off_delay_s);
  return job;
}

JobResult run_job(const JobSpec& spec, const JobOptions& options, Sink<ScanSample>& device) {
  JobResult result;
  // The drain thread is waiting on the line memory before the clock starts, so the compile time
  // measures the text's way to the first sample and nothing else.
  LineMemory<ScanSample> memory(options.memory_samples);
  DrainOptions drain_options;
  drain_options.rate_hz = 1.0 / spec.pen.tick_s;
  drain_options.virtual_time = options.virtual_time;
  // The delay line needs its delays, which come from the compiled pen; it is configured before
  // the first sample reaches the drain.
  LaserDelayLine delay(spec.pen.ticks(spec.pen.laser_on_delay_s),
                       spec.pen.ticks(spec.pen.laser_off_delay_s));
  Drain<ScanSample> drain(memory, device, drain_options, &delay);
  drain.start();

  const Clock::time_point t0 = Clock::now();
  try {
    result.job = compile_job(spec);
  } catch (...) {
    drain.abort();  // the device saw no sample; halt() leaves its laser off
    drain.join();
    throw;
  }
  const std::vector<Command>& commands = result.job.plan.commands;
  LocusGenerator locus(result.job.plan);
  const std::uint64_t total = options.progress ? LocusGenerator::count_samples(result.job.plan) : 0;

  std::vector<ScanSample> buffer(std::max(options.block, options.first_block));
  bool first = true;
  Clock::time_point last_report = Clock::now();
  while (std::size_t n = locus.generate(buffer.data(), first ? options.first_block : options.block)) {
    if (!memory.push(std::span<const ScanSample>(buffer.data(), n))) break;  // drain stopped
    if (first) result.compile_time_s = seconds_since(t0), first = false;
    if (options.progress && Clock::now() - last_report > std::chrono::milliseconds(100)) {
      options.progress(drain.samples_out(), total);
      last_report = Clock::now();
    }
  }
  memory.close();
  if (options.progress) {
    while (!memory.aborted() && drain.samples_out() < total) {
      options.progress(drain.samples_out(), total);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  result.drain = drain.join();
  result.wall_time_s = seconds_since(t0);
  if (options.progress) options.progress(total, total);

  result.glyphs = result.job.figure.glyphs.size();
  result.strokes = result.job.plan.strokes;
  result.commands = commands.size();
  result.samples = result.drain.samples_out;
  result.mark_time_s = static_cast<double>(result.samples) * spec.pen.tick_s;
  result.jump_length_mm = result.job.plan.jump_length_mm;
  return result;
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
