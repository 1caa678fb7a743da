#include "marker/gravure/stylus_run.hpp"

#include <algorithm>
#include <chrono>
#include <exception>

#include "driver/sim/stylus_head_model.hpp"
#include "ringbuffer/line_memory.hpp"

namespace mark {

StylusSampleStream::StylusSampleStream(DriveSource& source, const FilterBank* bank)
    : source_(source), filtered_(bank != nullptr), cascade_(bank ? BiquadCascade(*bank) : BiquadCascade()) {}

std::size_t StylusSampleStream::next(std::span<StylusSample> out) {
  drive_.resize(out.size());
  const std::size_t n = source_.next(drive_);
  if (n == 0) return 0;
  const std::span<double> d(drive_.data(), n);
  if (filtered_) {
    // The filters start at rest on the first value, as the head does: no start-up ring.
    if (!started_) cascade_.settle(d[0]);
    cascade_.process(d);
  }
  started_ = true;
  for (std::size_t i = 0; i < n; ++i) out[i] = {static_cast<float>(d[i]), false};
  return n;
}

StylusRunResult run_stylus_job(DriveSource& source, const FilterBank* bank, SampleDevice<StylusSample>& device,
                               const StylusRunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  StylusRunResult result;
  JobHeader header;
  header.name = options.job_name;
  header.field_mm = 0;
  header.pens.push_back({});
  header.expected_samples = source.total_samples();
  device.begin_job(header);

  StylusSampleStream stream(source, bank);  // before the drain starts: its filters are built here
  LineMemory<StylusSample> memory(std::max<std::size_t>(options.memory_samples, 1));
  DrainOptions d;
  d.rate_hz = kStylusRate_hz;
  d.block_samples = std::max<std::size_t>(options.block_samples, 1);
  d.virtual_time = options.virtual_time;
  d.start_fill = std::min(options.memory_samples, 2 * d.block_samples);
  d.realtime_priority = 0;
  d.stop = options.stop;
  d.stop_at = options.stop_at;
  d.starve_at = options.starve_at;
  Drain<StylusSample> drain(memory, device, d);
  drain.start();
  std::exception_ptr failure;
  try {
    std::vector<StylusSample> chunk(4096);
    while (const std::size_t n = stream.next(chunk)) {
      result.samples += n;
      if (!memory.push(std::span<const StylusSample>(chunk.data(), n))) break;  // the drain stopped
    }
    memory.close();
  } catch (...) {
    // The producer failed: stop the drain (the stylus gets its safe sample) before reporting.
    failure = std::current_exception();
    drain.abort();
  }
  result.drain = drain.wait();
  result.report = device.end_job();
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (failure) std::rethrow_exception(failure);

  const DrainStats& st = result.drain;
  switch (st.end) {
    case DrainEnd::completed:
      result.fault = result.report.fault;
      break;
    case DrainEnd::cancelled:
      result.cancelled = true;
      break;
    case DrainEnd::underrun:
      result.fault = DeviceFault{FaultCategory::underrun,
                                 "line memory underrun at sample " + std::to_string(st.stop_sample) +
                                     ": the toolpath fell behind the stylus clock; stylus lifted for the rest of the job",
                                 st.stop_sample};
      break;
    case DrainEnd::device_fault:
      result.fault = fault_from(drain.error(), st.stop_sample);
      break;
  }
  if (st.end != DrainEnd::completed) result.stopped_at = result.fault ? result.fault->at : st.stop_sample;
  return result;
}

}  // namespace mark
