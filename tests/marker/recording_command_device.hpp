#pragma once
// A command-level device for tests: records every command submitted, "executes" each at once,
// honours abort() (the rest is not executed) and can fail at a given command.
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "driver/device.hpp"

namespace mark::test {

class RecordingCommandDevice : public CommandDevice {
 public:
  DeviceDescription description;
  std::vector<DeviceCommand> received;
  std::vector<JobHeader> headers;
  long fail_at = -1;  // throw a transport fault when this command index arrives
  long error_at = -1;  // throw an error that is not a device fault (a bug, bad_alloc) there

  RecordingCommandDevice() {
    description.name = "recording board";
    description.level = DeviceLevel::commands;
    description.field_mm = 110;
    description.arcs = false;
    description.chord_tolerance_mm = 0.005;
  }
  DeviceDescription describe() const override { return description; }
  void begin_job(const JobHeader& h) override {
    headers.push_back(h);
    state_ = DeviceState::running;
  }
  void submit(std::span<const DeviceCommand> commands) override {
    for (const DeviceCommand& c : commands) {
      if (state_ != DeviceState::running) return;  // aborted: the rest is not executed
      if (fail_at >= 0 && static_cast<long>(received.size()) == fail_at) {
        state_ = DeviceState::failed;
        fault_ = DeviceFault{FaultCategory::transport, "recording board: unplugged", received.size()};
        throw DeviceFaultError(*fault_);
      }
      if (error_at >= 0 && static_cast<long>(received.size()) == error_at)
        throw std::runtime_error("recording board: not a fault");
      received.push_back(c);
    }
  }
  DeviceReport end_job() override {
    DeviceReport r;
    if (state_ == DeviceState::running) state_ = DeviceState::done;
    r.outcome = state_;
    r.fault = fault_;
    r.commands_done = received.size();
    return r;
  }
  void abort() noexcept override {
    aborts++;
    DeviceState s = DeviceState::running;
    state_.compare_exchange_strong(s, DeviceState::aborted);
  }
  DeviceStatus status() const override { return {state_.load(), {}, false, fault_, received.size()}; }
  void reset() override {
    state_ = DeviceState::idle;
    fault_.reset();
  }
  std::atomic<int> aborts{0};

 private:
  std::atomic<DeviceState> state_{DeviceState::idle};
  std::optional<DeviceFault> fault_;
};

}  // namespace mark::test
