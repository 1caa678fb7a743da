#pragma once
// What a drain did, returned by Drain::join().
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace mark {

enum class DrainEnd {
  completed,     // the memory was closed and everything in it went out
  cancelled,     // a stop was requested (StopFlag, abort(), stop_at) and honoured
  underrun,      // the memory ran dry mid-job: a fault; the laser went out at stop_sample
  device_fault   // the device threw; join() rethrows its error
};

struct DrainStats {
  DrainEnd end = DrainEnd::completed;
  // cancelled / underrun / device_fault: index of the first sample the device did not get as
  // planned (the first missing one for an underrun, the first not sent for a stop).
  std::uint64_t stop_sample = 0;
  std::uint64_t samples_out = 0;       // every sample handed to the device (incl. safe samples)
  std::uint64_t blocks = 0;            // device writes
  std::uint64_t underrun_events = 0;   // 1 when the job ended in an underrun
  std::uint64_t underrun_samples = 0;  // safe samples that padded the starved block
  std::size_t peak_fill = 0;           // highest line-memory fill seen, samples
  double lateness_median_us = 0;       // real time only: block output after its deadline
  double lateness_p99_us = 0;
  double lateness_max_us = 0;
  bool realtime_granted = false;       // the drain thread got SCHED_FIFO
  // A stop requested through a StopFlag: wall time from the request to the device halted, and
  // (real time) samples the device got after the request fell on its clock. −1 / 0 otherwise.
  double stop_latency_us = -1;
  std::uint64_t stop_latency_samples = 0;
  // When the device got its first block (steady clock; the epoch when it got none): trigger-to-
  // first-sample latency is measured from a caller's own clock reading against it.
  std::chrono::steady_clock::time_point first_write{};
};

const char* to_string(DrainEnd end);

}  // namespace mark
