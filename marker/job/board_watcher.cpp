#include "marker/job/board_watcher.hpp"

#include <algorithm>
#include <chrono>

namespace mark {

BoardStopWatcher::BoardStopWatcher(CommandDevice& device, const StopFlag* stop) : device_(device), stop_(stop) {
  if (!stop_) return;
  thread_ = std::thread([this] {
    while (!finished_.load(std::memory_order_acquire)) {
      if (stop_->requested()) return stop_board();
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
}

void BoardStopWatcher::stop_board() noexcept {
  device_.abort();
  std::int64_t none = 0;
  aborted_at_ns_.compare_exchange_strong(none, StopFlag::now_ns(), std::memory_order_acq_rel);
}

void BoardStopWatcher::finish() {
  finished_.store(true, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
}

double BoardStopWatcher::stop_latency_us() const {
  const std::int64_t asked = stop_ ? stop_->requested_at_ns() : 0;
  const std::int64_t aborted = aborted_at_ns_.load(std::memory_order_acquire);
  return asked > 0 && aborted >= asked ? static_cast<double>(aborted - asked) / 1e3 : -1;
}

DeviceReport run_board_program(CommandDevice& device, const JobHeader& header,
                               std::span<const DeviceCommand> commands, const StopFlag* stop) {
  device.begin_job(header);
  BoardStopWatcher watcher(device, stop);
  constexpr std::size_t kChunk = 256;
  std::optional<DeviceFault> fault;
  for (std::size_t i = 0; i < commands.size(); i += kChunk) {
    if (watcher.stop_requested()) {
      watcher.stop_board();
      break;
    }
    try {
      device.submit(commands.subspan(i, std::min(kChunk, commands.size() - i)));
    } catch (const DeviceFaultError& e) {
      fault = e.fault();
      break;
    } catch (...) {
      watcher.stop_board();  // whatever went wrong, the board is not left running with the laser
      throw;
    }
  }
  DeviceReport report = device.end_job();
  watcher.finish();
  if (!report.fault && fault) {
    report.fault = fault;
    report.outcome = DeviceState::failed;
  }
  return report;
}

}  // namespace mark
