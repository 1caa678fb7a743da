#pragma once
// The two ways a compiled job reaches a device (internal to marker/job): samples through the
// line memory and the fixed-rate drain, or device commands submitted to a vector board. Both
// fill the result's outcome, stop point, ink marked and device report.
#include <chrono>

#include "marker/job/job.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark {

using JobClock = std::chrono::steady_clock;

double seconds_since(JobClock::time_point t0);

// What begin_job tells the device: the field, the pen, the expected samples and the lit paths.
JobHeader job_header(const JobSpec& spec, const CompiledJob& job, const DeviceDescription& device);

// The job's outcome for how a device's job ended (done, failed; anything else aborted).
JobOutcome job_outcome(DeviceState ending);

// Sample level: begin_job with `header`, the stream, end_job (driver/sample_stream.hpp).
// `compiled_s`: the compile's wall time, the first part of compile_time_s (the second is the
// locus's first block, device setup left out).
void run_samples(const JobSpec& spec, const JobOptions& options, SampleDevice<ScanSample>& device,
                 const JobHeader& header, double compiled_s, JobResult& result);

// Command level; converts the plan, calls begin_job, submits, end_job.
void run_commands(const JobSpec& spec, const JobOptions& options, CommandDevice& device,
                  JobResult& result);

// Share of the locus's lit samples among its first `samples` (1 when the locus has none lit).
double locus_ink_fraction(const Plan& plan, std::uint64_t samples);

}  // namespace mark
