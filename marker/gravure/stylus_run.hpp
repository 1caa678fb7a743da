#pragma once
// A stylus job end to end, the same way the laser runs: the drive source (toolpath or test
// pattern) is filtered by the tuning biquads on the producer thread — every sample, before it
// enters the line memory — and written into LineMemory<StylusSample>, which the fixed-rate
// Drain<StylusSample> reads out at 200 kHz into a sample-level device. In virtual time (the
// default for the simulated head) the drain runs as fast as the device takes samples; device
// time is what is reported either way.
//
// The streaming and its endings are the one core every sample-level job shares
// (driver/sample_stream.hpp): the end of the job, a stop request (Ctrl-C through a StopFlag, or
// the injected stop_at; an abort() of the head from another thread), an underrun in real time,
// a device fault — and every one leaves the stylus on its safe sample, lifted clear of the
// cylinder. The result says which, and where the job stopped.
#include <cstdint>
#include <optional>
#include <string>

#include "driver/device.hpp"
#include "marker/gravure/biquad_cascade.hpp"
#include "marker/gravure/drive_source.hpp"
#include "marker/gravure/tuning_filter.hpp"
#include "ringbuffer/drain.hpp"
#include "ringbuffer/stylus_sample.hpp"

namespace mark {

// Filters a drive source into stylus samples (the producer's work, without the line memory):
// what the benchmark measures and what run_stylus_job feeds the memory with.
class StylusSampleStream {
 public:
  // bank may be null (unfiltered drive).
  StylusSampleStream(DriveSource& source, const FilterBank* bank);
  std::uint64_t total_samples() const { return source_.total_samples(); }
  std::size_t next(std::span<StylusSample> out);

 private:
  DriveSource& source_;
  bool filtered_;
  BiquadCascade cascade_;
  std::vector<double> drive_;
  bool started_ = false;
};

struct StylusRunOptions {
  bool virtual_time = true;
  std::size_t memory_samples = 1u << 16;  // 0.33 s at 200 kHz
  std::size_t block_samples = 200;        // drain block: 1 ms, the bound on stop latency
  std::string job_name = "gravure";
  const StopFlag* stop = nullptr;         // Ctrl-C, an operator; not owned
  std::uint64_t stop_at = kNever;         // tests: stop as if requested at this sample
  std::uint64_t starve_at = kNever;       // tests: the memory looks empty from this sample on
};

struct StylusRunResult {
  DeviceReport report;            // the device's outcome, fault, samples out, device time
  DrainStats drain;               // how the drain ended (completed, cancelled, underrun, fault)
  std::uint64_t samples = 0;      // samples the producer generated
  double wall_time_s = 0;
  bool cancelled = false;         // a stop request (or an abort of the head) ended the job
  std::optional<DeviceFault> fault;  // an underrun or a device fault ended it
  std::uint64_t stopped_at = 0;   // first sample not engraved as planned (when not completed)
};

StylusRunResult run_stylus_job(DriveSource& source, const FilterBank* bank,
                               SampleDevice<StylusSample>& device, const StylusRunOptions& options);

}  // namespace mark
