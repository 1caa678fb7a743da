#include "marker/gravure/stylus_run.hpp"

#include <algorithm>
#include <chrono>

#include "driver/sample_stream.hpp"
#include "driver/sim/stylus_head_model.hpp"

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
  JobHeader header;
  header.name = options.job_name;
  header.field_mm = 0;
  header.pens.push_back({});
  header.expected_samples = source.total_samples();

  StylusSampleStream stream(source, bank);  // before the drain starts: its filters are built here
  StreamOptions<StylusSample> o;
  o.memory_samples = std::max<std::size_t>(options.memory_samples, 1);
  o.drain.rate_hz = kStylusRate_hz;
  o.drain.block_samples = std::max<std::size_t>(options.block_samples, 1);
  o.drain.virtual_time = options.virtual_time;
  o.drain.start_fill = std::min(o.memory_samples, 2 * o.drain.block_samples);
  o.drain.realtime_priority = 0;
  o.drain.stop = options.stop;
  o.drain.stop_at = options.stop_at;
  o.drain.starve_at = options.starve_at;
  o.safe_state = "stylus lifted";
  const StreamResult s = stream_samples(
      device, header, [&](std::span<StylusSample> out) { return stream.next(out); }, o);

  StylusRunResult result;
  result.report = s.device;
  result.drain = s.drain;
  result.samples = s.produced;
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.cancelled = s.ending.outcome == DeviceState::aborted;
  result.fault = s.ending.fault;
  result.stopped_at = s.ending.stopped_at;
  return result;
}

}  // namespace mark
