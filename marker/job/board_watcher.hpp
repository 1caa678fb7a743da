#pragma once
// A stop request reaching a command-level board (a vector board with its own clock): a watcher
// thread turns it into device.abort() whether the host is still submitting commands or the
// board is finishing the ones it has. run_commands (a planned job) and run_board_program (a bare
// program, such as the head's lag test pattern) share it.
#include <atomic>
#include <cstdint>
#include <span>
#include <thread>

#include "driver/device.hpp"
#include "ringbuffer/stop_flag.hpp"

namespace mark {

class BoardStopWatcher {
 public:
  // Watches `stop` (none: nothing to watch) until finish().
  BoardStopWatcher(CommandDevice& device, const StopFlag* stop);
  ~BoardStopWatcher() { finish(); }
  BoardStopWatcher(const BoardStopWatcher&) = delete;
  BoardStopWatcher& operator=(const BoardStopWatcher&) = delete;

  // Aborts the board now (laser off) and notes when: the first call's time is kept.
  void stop_board() noexcept;
  // Whether a stop was requested (the submitting loop stops at once rather than at the watcher's
  // next poll).
  bool stop_requested() const { return stop_ && stop_->requested(); }
  // The board's job has ended: the watcher stops. Idempotent.
  void finish();
  // From the stop request to the abort (µs); -1 when no stop was requested or the board was
  // not aborted after it.
  double stop_latency_us() const;

 private:
  CommandDevice& device_;
  const StopFlag* stop_;
  std::atomic<bool> finished_{false};
  std::atomic<std::int64_t> aborted_at_ns_{0};
  std::thread thread_;
};

// A bare program on a command-level board, as one job: begin_job with `header`, the commands
// submitted in chunks, end_job. A stop request aborts the board (laser off) and ends the
// submission; the report says how far it got. The device must be idle (it stays in its final
// state; the caller resets it). A header the board refuses propagates before anything is sent;
// any other error while submitting aborts the board (laser off) and propagates.
DeviceReport run_board_program(CommandDevice& device, const JobHeader& header,
                               std::span<const DeviceCommand> commands, const StopFlag* stop);

}  // namespace mark
