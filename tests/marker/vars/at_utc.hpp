#pragma once
// A UTC wall-clock instant for the fixed clocks of the variables tests.
#include <chrono>

#include <date/date.h>

#include "marker/vars/clock.hpp"

namespace mark::test {

inline SysTime at_utc(int y, unsigned m, unsigned d, int hh, int mm) {
  using namespace std::chrono;
  return SysTime{date::sys_days{date::year{y} / m / d}} + hours{hh} + minutes{mm};
}

}  // namespace mark::test
