#pragma once
// How a streamed sample-level job ended, from the drain's ending and the device's report — the
// one classification every sample-level job uses (driver/sample_stream.hpp):
//
//   drain completed  → done, or failed when the device reports a fault of its own
//   drain cancelled  → aborted (a stop request, Ctrl-C, an injected stop)
//   drain underrun   → failed: an underrun fault at the first missing sample
//   device fault     → aborted when the device was aborted from outside and kept no fault (it
//                      refused the next block: that is the abort, not a failure), else failed
//                      with the fault the device threw
//
// Where it stopped (not done): the fault's own index when there is one, else the drain's stop
// sample — the first sample that was not output as planned.
#include <cstdint>
#include <exception>
#include <optional>
#include <string_view>

#include "driver/device.hpp"
#include "ringbuffer/drain_stats.hpp"

namespace mark {

struct StreamEnding {
  DeviceState outcome = DeviceState::done;  // done, aborted or failed
  std::optional<DeviceFault> fault;         // failed: what stopped the job
  std::uint64_t stopped_at = 0;             // not done: the first sample not output as planned
};

// `error`: what the device threw (Drain::error()); `safe_state` says what the sample type's safe
// sample means ("laser off", "stylus lifted"), for the underrun's message.
StreamEnding classify_ending(const DrainStats& drain, std::exception_ptr error,
                             const DeviceReport& device, std::string_view safe_state);

}  // namespace mark
