#pragma once
// Ctrl-C and SIGTERM become a stop request while a job runs: the handler only sets a StopFlag
// (async-signal-safe), the drain puts the laser out within one block and the command reports
// where it stopped and exits 130. Outside the scope the previous handlers are back.
#include <csignal>
#include <cstdint>

#include "ringbuffer/stop_flag.hpp"

namespace mark::cli {

class InterruptScope {
 public:
  explicit InterruptScope(StopFlag& flag);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  // The signal that requested the stop (SIGINT, SIGTERM), or 0.
  int signal() const;

 private:
  struct sigaction old_int_{}, old_term_{};
};

// The stop flag of the running command: cli::run() installs an InterruptScope on it around
// every command, so Ctrl-C reaches whatever the command polls (a job's drain, a planner).
StopFlag& interrupt_flag();

// How many SIGINT / SIGTERM this process received: a wait that sees it change was asked to
// stop (the serial store ends a lock or server wait on a new Ctrl-C even while the stop flag
// is already set by an earlier one).
std::uint64_t interrupt_count();

// Exit status of a command stopped by a signal: 128 + SIGINT, as shells report it.
inline constexpr int kExitInterrupted = 130;
// A production part marked but rejected by its verification (a code not read back): 2, as
// `marker code` exits for a code that does not read.
inline constexpr int kExitRejected = 2;

}  // namespace mark::cli
