// The stop request a drain polls: whoever sees it requested also sees when it was asked (the
// drain reports the latency from that time), the first request's time is kept, and reset()
// clears both for the next job.
#include "ringbuffer/stop_flag.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace mark {
namespace {

TEST(StopFlag, FirstRequestKeepsItsTimeAndResetClearsIt) {
  StopFlag f;
  EXPECT_FALSE(f.requested());
  EXPECT_EQ(f.requested_at_ns(), 0);
  const std::int64_t before = StopFlag::now_ns();
  f.request();
  EXPECT_TRUE(f.requested());
  const std::int64_t first = f.requested_at_ns();
  EXPECT_GE(first, before);
  EXPECT_LE(first, StopFlag::now_ns());
  f.request();
  EXPECT_EQ(f.requested_at_ns(), first);
  f.reset();
  EXPECT_FALSE(f.requested());
  EXPECT_EQ(f.requested_at_ns(), 0);
}

// A poller on another thread that sees requested() must never read a time of 0: Ctrl-C under
// load once left a job without its stop latency that way (the flag was set before the time).
TEST(StopFlag, APollerThatSeesTheRequestSeesItsTime) {
  for (int round = 0; round < 2000; ++round) {
    StopFlag f;
    std::atomic<bool> go{false};
    std::int64_t seen = -1;
    std::thread poller([&] {
      go.store(true, std::memory_order_release);
      while (!f.requested()) {
      }
      seen = f.requested_at_ns();
    });
    while (!go.load(std::memory_order_acquire)) {
    }
    f.request();
    poller.join();
    ASSERT_GT(seen, 0) << "round " << round;
  }
}

}  // namespace
}  // namespace mark
