#pragma once
// A request to stop a job from outside: Ctrl-C (a signal handler), an operator's stop button, a
// PLC. request() is async-signal-safe (lock-free atomics and clock_gettime), so a
// SIGINT handler may call it; the drain polls requested() after every wait and puts the laser
// out within one block. The request's time is kept so the drain can report the latency from
// the request to laser off.
#include <atomic>
#include <cstdint>
#include <ctime>

#include "base/progress.hpp"  // Interrupted: what a stopped computation throws

namespace mark {

class StopFlag {
 public:
  static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<std::int64_t>::is_always_lock_free,
                "a signal handler may only touch lock-free atomics");

  // The time goes in before the flag: a drain that sees requested() also sees when. The other
  // order left a window (wide when the handler is preempted) in which a stop had no time and
  // the job reported no stop latency. The first request's time is kept.
  void request() noexcept {
    std::int64_t none = 0;
    requested_at_ns_.compare_exchange_strong(none, now_ns(), std::memory_order_acq_rel);
    requested_.store(true, std::memory_order_release);
  }
  bool requested() const noexcept { return requested_.load(std::memory_order_acquire); }
  // steady-clock (CLOCK_MONOTONIC) time of the first request in ns; 0 while none was made.
  std::int64_t requested_at_ns() const noexcept {
    return requested_at_ns_.load(std::memory_order_acquire);
  }
  // Clear for the next job (not while a job is running).
  void reset() noexcept {
    requested_at_ns_.store(0, std::memory_order_release);
    requested_.store(false, std::memory_order_release);
  }

  // CLOCK_MONOTONIC in ns: the clock std::chrono::steady_clock reads on Linux, and one
  // clock_gettime is async-signal-safe where steady_clock::now() is not promised to be.
  static std::int64_t now_ns() noexcept {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
  }

 private:
  std::atomic<bool> requested_{false};
  std::atomic<std::int64_t> requested_at_ns_{0};
};

}  // namespace mark
