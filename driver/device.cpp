#include "driver/device.hpp"

namespace mark {

DeviceStateError::DeviceStateError(std::string device, std::string call, DeviceState state,
                                   std::string_view why)
    : DeviceError(device + ": " + call + " while " + std::string(to_string(state)) + "; " +
                  std::string(why)),
      device_(std::move(device)),
      call_(std::move(call)),
      state_(state) {}

DeviceFault fault_from(std::exception_ptr error, std::uint64_t at) {
  try {
    std::rethrow_exception(error);
  } catch (const DeviceFaultError& e) {
    return e.fault();
  } catch (const std::exception& e) {
    return {FaultCategory::device, e.what(), at};
  } catch (...) {
  }
  return {FaultCategory::device, "unknown device error", at};
}

std::string_view to_string(DeviceLevel level) {
  switch (level) {
    case DeviceLevel::samples: return "samples";
    case DeviceLevel::commands: return "commands";
  }
  return "?";
}

std::string_view to_string(DeviceState state) {
  switch (state) {
    case DeviceState::idle: return "idle";
    case DeviceState::running: return "running";
    case DeviceState::done: return "done";
    case DeviceState::aborted: return "aborted";
    case DeviceState::failed: return "failed";
  }
  return "?";
}

std::string_view to_string(FaultCategory category) {
  switch (category) {
    case FaultCategory::transport: return "transport";
    case FaultCategory::timeout: return "timeout";
    case FaultCategory::underrun: return "underrun";
    case FaultCategory::out_of_field: return "out_of_field";
    case FaultCategory::device: return "device";
  }
  return "?";
}

}  // namespace mark
