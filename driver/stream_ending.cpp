#include "driver/stream_ending.hpp"

#include <string>

namespace mark {

StreamEnding classify_ending(const DrainStats& drain, std::exception_ptr error,
                             const DeviceReport& device, std::string_view safe_state) {
  StreamEnding e;
  switch (drain.end) {
    case DrainEnd::completed:
      if (device.outcome == DeviceState::failed) e.outcome = DeviceState::failed;
      e.fault = device.fault;
      break;
    case DrainEnd::cancelled:
      e.outcome = DeviceState::aborted;
      break;
    case DrainEnd::underrun:
      e.outcome = DeviceState::failed;
      e.fault = DeviceFault{FaultCategory::underrun,
                            "line memory underrun at sample " + std::to_string(drain.stop_sample) +
                                ": the producer fell behind the device's clock; " +
                                std::string(safe_state) + " for the rest of the job",
                            drain.stop_sample};
      break;
    case DrainEnd::device_fault:
      if (device.outcome == DeviceState::aborted && !device.fault) {
        e.outcome = DeviceState::aborted;
      } else {
        e.outcome = DeviceState::failed;
        e.fault = fault_from(error, drain.stop_sample);
      }
      break;
  }
  if (e.outcome != DeviceState::done) e.stopped_at = e.fault ? e.fault->at : drain.stop_sample;
  return e;
}

}  // namespace mark
