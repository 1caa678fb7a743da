#pragma once
// The clock variable text reads (dates, shift codes, counter resets). Injected everywhere so
// tests run on fixed instants; production uses the system clock.
#include <chrono>

namespace mark {

using SysTime = std::chrono::sys_time<std::chrono::microseconds>;

class Clock {
 public:
  virtual ~Clock() = default;
  virtual SysTime now() const = 0;
};

class SystemClock : public Clock {
 public:
  SysTime now() const override {
    return std::chrono::time_point_cast<std::chrono::microseconds>(std::chrono::system_clock::now());
  }
};

// A clock that stands still until told otherwise (tests, replays).
class FixedClock : public Clock {
 public:
  explicit FixedClock(SysTime t) : t_(t) {}
  SysTime now() const override { return t_; }
  void set(SysTime t) { t_ = t; }
  void advance(std::chrono::microseconds d) { t_ += d; }

 private:
  SysTime t_;
};

}  // namespace mark
