// A job on a sample-level device: the locus generator is the producer of the one streaming
// core (driver/sample_stream.hpp), the laser delay line its filter on the drain thread.
#include <algorithm>
#include <cmath>
#include <vector>

#include "driver/sample_stream.hpp"
#include "marker/job/job_run.hpp"
#include "marker/locus/locus_generator.hpp"
#include "ringbuffer/laser_delay_line.hpp"

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
                 const JobHeader& header, double compiled_s, JobResult& result) {
  const Plan& plan = result.job.plan;
  LaserDelayLine delay(result.job.laser_on_ticks, result.job.laser_off_ticks);
  LocusGenerator locus(plan);
  StreamOptions<ScanSample> o;
  o.drain = drain_options(spec, options, device.describe());
  o.filter = &delay;
  o.memory_samples = options.memory_samples;
  o.first_block = options.first_block;
  o.block = options.block;
  // Everything the job touches is allocated before the drain starts; lock it in RAM so no page
  // fault stalls the drain (real time only: virtual time has no deadlines to miss).
  o.lock_memory = !options.virtual_time && options.realtime;
  o.progress = options.progress;
  o.total_samples = options.progress ? LocusGenerator::count_samples(plan) : 0;
  const StreamResult s = stream_samples(
      device, header, [&](std::span<ScanSample> out) { return locus.generate(out.data(), out.size()); }, o);

  result.compile_time_s = compiled_s + s.first_block_s;
  result.memory_locked = s.memory_locked;
  result.device = s.device;
  result.drain = s.drain;
  result.samples = s.drain.samples_out;
  result.mark_time_s = static_cast<double>(s.drain.samples_out) * spec.pen.tick_s;
  result.commands = plan.commands.size();
  result.stop_latency_us = s.drain.stop_latency_us;
  result.stop_latency_samples = s.drain.stop_latency_samples;
  result.outcome = job_outcome(s.ending.outcome);
  result.fault = s.ending.fault;
  if (result.outcome != JobOutcome::done) {
    result.stopped_at = s.ending.stopped_at;
    result.ink_marked = locus_ink_fraction(plan, result.stopped_at);
  }
}

}  // namespace mark
