#pragma once
// The one job lifecycle of driver/device.hpp as a small state machine every device embeds: the
// state, the fault that failed the job, the abort request and the host's halt, the
// transitions, and the status snapshot. A device calls these at the top of its own begin_job,
// end_job, abort, reset, write or submit and adds only what it does to its hardware (laser
// off, buffers sized, a stop sequence on the wire).
//
// Threads: abort() and the queries are lock-free and callable from any thread at any time
// (abort is noexcept and never waits: a station calls it from its network thread). The other
// transitions are the owner's (the thread that runs the job; the drain's halt()); a fault is
// kept under a mutex so status() sees the state and its fault together, and the sample path
// never takes it except when a fault happens.
#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

#include "driver/device.hpp"

namespace mark {

class Lifecycle {
 public:
  // `device`: the name messages give (describe().name).
  explicit Lifecycle(std::string device);

  // The name can change once the device knows it (a board's serial after its init); only the
  // owner's thread uses it, for messages.
  void rename(std::string device) { device_ = std::move(device); }
  const std::string& device() const { return device_; }

  // idle → running (begin_job; `call` names the call for the message: "frame", or "write" for
  // the simulated scanner's implicit job). Throws DeviceStateError in any other state and
  // changes nothing.
  void begin(std::string_view call);
  // A job's end: running → done, or aborted when the job was aborted or halted, or failed when
  // a fault was kept; a final state stays as it is. Returns the state now. Throws
  // DeviceStateError when idle: there is no job to end.
  DeviceState end(std::string_view call = "end_job");
  // An operation that is not a job (a red-pointer frame) ends: running → idle. Aborted or
  // failed stay.
  void leave();
  // done / aborted / failed → idle, idle stays idle; clears the fault, the abort request and
  // the halt. Throws DeviceStateError while running.
  void reset(std::string_view call = "reset");
  // idle / running → aborted and the abort request raised; a final state is kept.
  void abort() noexcept;
  // The host stopped feeding (the drain on a stop, an underrun or a fault): the job will end
  // aborted unless a fault failed it. The state stays running until end().
  void halt() noexcept { halted_.store(true, std::memory_order_release); }
  // A fault stopped the job: idle / running → failed, the fault kept (the first one). Aborted
  // stays aborted and failed keeps its first fault. Returns the fault as given, for the
  // device to throw.
  const DeviceFault& fail(const DeviceFault& fault);
  // Throws DeviceStateError unless the state is `want`; `why` says what the call needs.
  void require(DeviceState want, std::string_view call, std::string_view why) const;
  // Throws DeviceStateError for `call` in the state the device is in now.
  [[noreturn]] void refuse(std::string_view call, std::string_view why) const;

  // Queries (any thread).
  DeviceState state() const noexcept { return state_.load(std::memory_order_acquire); }
  bool abort_requested() const noexcept { return abort_.load(std::memory_order_acquire); }
  // The laser must stay off: the job was aborted or halted, or it failed.
  bool stopped() const noexcept {
    return abort_requested() || halted_.load(std::memory_order_acquire) ||
           state() == DeviceState::failed;
  }
  // The abort request as a flag a device's own layers can watch (the LMC session's waits).
  const std::atomic<bool>& abort_flag() const noexcept { return abort_; }
  std::optional<DeviceFault> fault() const;
  // The state and the fault, together; the device adds position, laser and progress.
  DeviceStatus snapshot() const;

 private:
  [[noreturn]] void refuse(std::string_view call, DeviceState state, std::string_view why) const;

  std::string device_;
  std::atomic<DeviceState> state_{DeviceState::idle};
  std::atomic<bool> abort_{false};
  std::atomic<bool> halted_{false};
  mutable std::mutex fault_mutex_;  // fault_, and the transitions into and out of failed
  std::optional<DeviceFault> fault_;
};

}  // namespace mark
