#pragma once
// Ctrl-C and SIGTERM during a long job: while an InterruptGuard lives, the signals only set a
// flag that the job polls (it then stops cleanly: laser off, stylus lifted, nothing half
// written); the previous handlers come back when the guard goes.
namespace mark::cli {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // A signal arrived since the guard was made.
  static bool requested();
};

}  // namespace mark::cli
