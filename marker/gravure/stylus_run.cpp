#include "marker/gravure/stylus_run.hpp"

#include <algorithm>
#include <chrono>
#include <exception>

#include "driver/stylus_head_model.hpp"
#include "ringbuffer/drain.hpp"
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

  StylusSampleStream stream(source, bank);
  LineMemory<StylusSample> memory(std::max<std::size_t>(options.memory_samples, 1));
  DrainOptions drain_options;
  drain_options.rate_hz = kStylusRate_hz;
  drain_options.block_samples = std::max<std::size_t>(options.block_samples, 1);
  drain_options.virtual_time = options.virtual_time;
  Drain<StylusSample> drain(memory, device, drain_options);
  drain.start();
  std::exception_ptr failure;
  try {
    std::vector<StylusSample> chunk(4096);
    for (;;) {
      if (options.cancelled && options.cancelled()) {
        result.cancelled = true;
        device.abort();
        drain.abort();
        break;
      }
      const std::size_t n = stream.next(chunk);
      if (n == 0) break;
      result.samples += n;
      if (!memory.push(std::span<const StylusSample>(chunk.data(), n))) break;  // aborted: a fault
    }
    memory.close();
  } catch (...) {
    // The producer failed: stop the drain and the device (stylus lifted) before reporting.
    failure = std::current_exception();
    device.abort();
    drain.abort();
  }
  try {
    result.drain = drain.join();
  } catch (const DeviceFaultError&) {
    // The fault is in the device's report; the device retracted the stylus already.
  } catch (...) {
    // After a cancel the aborted device refuses the drain's next block: that is how the drain
    // learns to stop, not a failure.
    if (!failure && !result.cancelled) failure = std::current_exception();
  }
  result.report = device.end_job();
  if (failure) std::rethrow_exception(failure);
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace mark
