// A job on a sample-level device: the locus generator writes the line memory on this thread
// while the drain thread reads it out through the laser delay line to the device.
#include <algorithm>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "marker/job/job_run.hpp"
#include "marker/locus/locus_generator.hpp"
#include "ringbuffer/drain.hpp"
#include "ringbuffer/laser_delay_line.hpp"
#include "ringbuffer/line_memory.hpp"
#include "ringbuffer/realtime.hpp"

namespace mark {
namespace {

DrainOptions drain_options(const JobSpec& spec, const JobOptions& options,
                           const DeviceDescription& device) {
  DrainOptions d;
  d.rate_hz = 1.0 / spec.pen.tick_s;
  // 1 ms blocks: the stop latency bound and the scheduling granularity of the drain.
  d.block_samples = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(1e-3 / spec.pen.tick_s)));
  d.virtual_time = options.virtual_time;
  const std::size_t lead = options.lead_samples ? options.lead_samples : 50 * d.block_samples;
  d.start_fill = std::min(options.memory_samples, lead + device.fifo_samples);
  d.realtime_priority = options.realtime ? 80 : 0;
  d.stop = options.stop;
  if (options.inject.kind == Injection::Kind::underrun) d.starve_at = options.inject.at;
  if (options.inject.kind == Injection::Kind::abort) d.stop_at = options.inject.at;
  return d;
}

}  // namespace

double locus_ink_fraction(const Plan& plan, std::uint64_t samples) {
  LocusGenerator locus(plan);
  std::vector<ScanSample> block(4096);
  std::uint64_t seen = 0, lit_before = 0, lit_total = 0;
  while (std::size_t n = locus.generate(block.data(), block.size())) {
    for (std::size_t i = 0; i < n; ++i) {
      if (!block[i].laser) continue;
      ++lit_total;
      if (seen + i < samples) ++lit_before;
    }
    seen += n;
  }
  return lit_total ? static_cast<double>(lit_before) / static_cast<double>(lit_total) : 1.0;
}

void run_samples(const JobSpec& spec, const JobOptions& options, SampleDevice<ScanSample>& device,
                 double compiled_s, JobResult& result) {
  const DeviceDescription desc = device.describe();
  const Plan& plan = result.job.plan;
  const double tick = spec.pen.tick_s;
  LineMemory<ScanSample> memory(options.memory_samples);
  LaserDelayLine delay(result.job.laser_on_ticks, result.job.laser_off_ticks);
  Drain<ScanSample> drain(memory, device, drain_options(spec, options, desc), &delay);
  std::vector<ScanSample> buffer(std::max(options.block, options.first_block));
  LocusGenerator locus(plan);
  const std::uint64_t total = options.progress ? LocusGenerator::count_samples(plan) : 0;
  // Everything the job touches is allocated now; lock it in RAM so no page fault stalls the
  // drain (real time only: virtual time has no deadlines to miss).
  if (!options.virtual_time && options.realtime) result.memory_locked = lock_memory();
  drain.start();

  const JobClock::time_point produce = JobClock::now();
  bool first = true;
  JobClock::time_point last_report = JobClock::now();
  while (std::size_t n = locus.generate(buffer.data(), first ? options.first_block : options.block)) {
    if (!memory.push(std::span<const ScanSample>(buffer.data(), n))) break;  // the drain stopped
    if (first) result.compile_time_s = compiled_s + seconds_since(produce), first = false;
    if (options.progress && JobClock::now() - last_report > std::chrono::milliseconds(100)) {
      options.progress(drain.samples_out(), total);
      last_report = JobClock::now();
    }
  }
  memory.close();
  if (options.progress) {
    while (!memory.aborted() && drain.samples_out() < total) {
      options.progress(drain.samples_out(), total);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  result.drain = drain.wait();
  if (result.memory_locked) unlock_memory();
  result.device = device.end_job();

  const DrainStats& d = result.drain;
  result.samples = d.samples_out;
  result.mark_time_s = static_cast<double>(d.samples_out) * tick;
  result.commands = plan.commands.size();
  result.stop_latency_us = d.stop_latency_us;
  result.stop_latency_samples = d.stop_latency_samples;
  switch (d.end) {
    case DrainEnd::completed:
      result.outcome = result.device.outcome == DeviceState::failed ? JobOutcome::failed
                                                                    : JobOutcome::done;
      result.fault = result.device.fault;
      break;
    case DrainEnd::cancelled:
      result.outcome = JobOutcome::aborted;
      break;
    case DrainEnd::underrun:
      result.outcome = JobOutcome::failed;
      result.fault = DeviceFault{
          FaultCategory::underrun,
          "line memory underrun at sample " + std::to_string(d.stop_sample) +
              ": the producer fell behind the device; laser off for the rest of the job",
          d.stop_sample};
      break;
    case DrainEnd::device_fault:
      // A device that was told to abort from outside refuses the next block: that is an abort.
      if (result.device.outcome == DeviceState::aborted && !result.device.fault) {
        result.outcome = JobOutcome::aborted;
      } else {
        result.outcome = JobOutcome::failed;
        result.fault = fault_from(drain.error(), d.stop_sample);
      }
      break;
  }
  if (result.outcome != JobOutcome::done) {
    result.stopped_at = d.end == DrainEnd::device_fault && result.fault ? result.fault->at : d.stop_sample;
    result.ink_marked = locus_ink_fraction(plan, result.stopped_at);
  }
}

}  // namespace mark
