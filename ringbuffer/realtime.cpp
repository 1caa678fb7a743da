#include "ringbuffer/realtime.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>

namespace mark {

bool request_realtime_priority(int priority) noexcept {
  sched_param param{};
  param.sched_priority = priority;
  return pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
}

bool lock_memory() noexcept { return mlockall(MCL_CURRENT) == 0; }

void unlock_memory() noexcept { munlockall(); }

}  // namespace mark
