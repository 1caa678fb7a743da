// Line memory under a real producer/consumer pair: nothing lost, nothing reordered, whatever the
// capacity and chunk sizes; abort releases a waiting producer.
#include "ringbuffer/line_memory.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <random>
#include <thread>
#include <vector>

namespace mark {
namespace {

// Sanitizer builds run ~10x slower; keep the sample counts sensible there.
#if defined(__SANITIZE_THREAD__)
constexpr std::uint64_t scale = 10;
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
constexpr std::uint64_t scale = 10;
#else
constexpr std::uint64_t scale = 1;
#endif
#else
constexpr std::uint64_t scale = 1;
#endif

struct Seq {
  std::uint64_t n = 0;
  std::uint64_t check = 0;  // n * constant: catches torn or mixed-up samples
};
constexpr std::uint64_t mix = 0x9e3779b97f4a7c15ull;

// Producer pushes 0..count-1 in random chunks; consumer pops in random chunks and checks order.
void stress(std::size_t capacity, std::uint64_t count, std::size_t max_chunk, unsigned seed) {
  LineMemory<Seq> memory(capacity);
  std::thread producer([&] {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::size_t> chunk(1, max_chunk);
    std::vector<Seq> buf(max_chunk);
    std::uint64_t next = 0;
    while (next < count) {
      const std::size_t n = std::min<std::uint64_t>(chunk(rng), count - next);
      bool stored = false;
      if (n == 1) {
        stored = memory.push(Seq{next, next * mix});
      } else {
        for (std::size_t i = 0; i < n; ++i) buf[i] = {next + i, (next + i) * mix};
        stored = memory.push(std::span<const Seq>(buf.data(), n));
      }
      EXPECT_TRUE(stored);
      if (!stored) break;
      next += n;
    }
    memory.close();
  });

  std::mt19937 rng(seed + 1);
  std::uniform_int_distribution<std::size_t> chunk(1, max_chunk);
  std::vector<Seq> out(max_chunk);
  std::uint64_t expect = 0;
  bool order_ok = true;
  for (;;) {
    const bool closed = memory.closed();
    const std::size_t n = memory.pop(std::span<Seq>(out.data(), chunk(rng)));
    for (std::size_t i = 0; i < n; ++i) {
      order_ok &= out[i].n == expect && out[i].check == expect * mix;
      ++expect;
    }
    if (n == 0) {
      if (closed) break;
      std::this_thread::yield();
    }
  }
  producer.join();
  EXPECT_TRUE(order_ok);
  EXPECT_EQ(expect, count);
  EXPECT_EQ(memory.pushed(), count);
  EXPECT_EQ(memory.popped(), count);
  EXPECT_EQ(memory.fill(), 0u);
  EXPECT_LE(memory.peak_fill(), capacity);
}

TEST(LineMemory, StressLargeCapacityMillionsOfSamples) { stress(1 << 14, 4'000'000 / scale, 512, 1); }
// With one or three slots nearly every push waits; under TSan each wait costs ~1 ms.
TEST(LineMemory, StressCapacityOne) { stress(1, 200'000 / (scale * scale), 4, 2); }
TEST(LineMemory, StressCapacityThree) { stress(3, 400'000 / (scale * scale), 7, 3); }
TEST(LineMemory, StressChunksLargerThanCapacity) { stress(64, 1'000'000 / scale, 1000, 4); }

TEST(LineMemory, PopTakesOldestFirstAndReportsFill) {
  LineMemory<int> memory(8);
  const int in[] = {1, 2, 3, 4, 5};
  ASSERT_TRUE(memory.push(std::span<const int>(in)));
  EXPECT_EQ(memory.fill(), 5u);
  int out[3];
  ASSERT_EQ(memory.pop(std::span<int>(out)), 3u);
  EXPECT_EQ(out[0], 1);
  EXPECT_EQ(out[2], 3);
  EXPECT_EQ(memory.fill(), 2u);
  EXPECT_EQ(memory.peak_fill(), 5u);
  ASSERT_EQ(memory.pop(std::span<int>(out)), 2u);
  EXPECT_EQ(out[1], 5);
  EXPECT_EQ(memory.pop(std::span<int>(out)), 0u);
}

TEST(LineMemory, AbortReleasesAWaitingProducer) {
  LineMemory<int> memory(4);
  std::atomic<int> result{-1};
  std::thread producer([&] {
    std::vector<int> many(100, 7);
    result = memory.push(std::span<const int>(many)) ? 1 : 0;  // blocks after 4
  });
  while (memory.fill() < 4) std::this_thread::yield();
  EXPECT_EQ(result.load(), -1);  // still waiting: the memory is full
  memory.abort();
  producer.join();
  EXPECT_EQ(result.load(), 0);
  EXPECT_TRUE(memory.aborted());
  EXPECT_EQ(memory.fill(), 4u);  // what was stored stays stored, nothing else
  EXPECT_FALSE(memory.push(1));
}

TEST(LineMemory, ZeroCapacityIsRefused) { EXPECT_THROW(LineMemory<int>(0), std::invalid_argument); }

}  // namespace
}  // namespace mark
