#pragma once
// What a drain did, returned by Drain::join().
#include <cstddef>
#include <cstdint>

namespace mark {

struct DrainStats {
  std::uint64_t samples_out = 0;       // every sample handed to the sink (incl. hold and flush)
  std::uint64_t blocks = 0;            // sink writes
  std::uint64_t underrun_events = 0;   // episodes of consecutive starved blocks
  std::uint64_t underrun_samples = 0;  // hold samples emitted because the memory was empty
  std::size_t peak_fill = 0;           // highest line-memory fill seen, samples
  double lateness_median_us = 0;       // real time only: block output after its deadline
  double lateness_p99_us = 0;
  double lateness_max_us = 0;
  bool aborted = false;                // stopped by abort() rather than by the end of the job
};

}  // namespace mark
