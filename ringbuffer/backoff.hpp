#pragma once
// Waiting without a lock: spin briefly (the other side is usually microseconds away), then
// yield, then sleep in short naps so a stalled partner does not burn a core. Used by the line
// memory's producer when the memory is full and by the drain in virtual time when it is empty.
#include <chrono>
#include <thread>

namespace mark {

class Backoff {
 public:
  void pause() {
    if (round_ < spin_rounds) {
      ++round_;
    } else if (round_ < spin_rounds + yield_rounds) {
      ++round_;
      std::this_thread::yield();
    } else {
      std::this_thread::sleep_for(std::chrono::microseconds(nap_us));
    }
  }
  void reset() { round_ = 0; }

 private:
  static constexpr int spin_rounds = 64;
  static constexpr int yield_rounds = 64;
  static constexpr int nap_us = 20;
  int round_ = 0;
};

}  // namespace mark
