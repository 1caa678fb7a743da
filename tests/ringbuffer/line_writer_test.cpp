// The batching writer: samples reach the memory in order, only in whole batches until flushed,
// and close() hands over the rest.
#include "ringbuffer/line_writer.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace mark {
namespace {

TEST(LineWriter, BatchesInOrderAndFlushesOnClose) {
  LineMemory<int> memory(1000);
  {
    LineWriter<int> writer(memory, 4);
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(writer.push(i));
    EXPECT_EQ(memory.fill(), 8u);  // two full batches; two samples staged
    EXPECT_EQ(writer.staged(), 2u);
    ASSERT_TRUE(writer.close());
  }
  EXPECT_TRUE(memory.closed());
  int out[20];
  ASSERT_EQ(memory.pop(std::span<int>(out)), 10u);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(out[i], i);
}

TEST(LineWriter, DestructorHandsOverStagedSamples) {
  LineMemory<int> memory(16);
  { LineWriter<int>(memory, 8).push(5); }
  EXPECT_EQ(memory.fill(), 1u);
}

TEST(LineWriter, StressThroughATinyMemory) {
  LineMemory<std::uint64_t> memory(5);
  constexpr std::uint64_t n = 20000;
  std::thread producer([&] {
    LineWriter<std::uint64_t> writer(memory, 7);
    for (std::uint64_t i = 0; i < n; ++i) writer.push(i);
    writer.close();
  });
  std::uint64_t expect = 0, buf[3];
  bool ok = true;
  for (;;) {
    const bool closed = memory.closed();
    const std::size_t got = memory.pop(std::span<std::uint64_t>(buf));
    for (std::size_t i = 0; i < got; ++i) ok &= buf[i] == expect++;
    if (got == 0 && closed) break;
    if (got == 0) std::this_thread::yield();
  }
  producer.join();
  EXPECT_TRUE(ok);
  EXPECT_EQ(expect, n);
}

TEST(LineWriter, ReportsAbort) {
  LineMemory<int> memory(16);
  LineWriter<int> writer(memory, 4);
  memory.abort();
  EXPECT_TRUE(writer.push(1));   // staged only: nothing handed over yet
  EXPECT_TRUE(writer.push(2));
  EXPECT_TRUE(writer.push(3));
  EXPECT_FALSE(writer.push(4));  // the batch is full: the hand-over finds the abort
  EXPECT_FALSE(writer.flush());
}

}  // namespace
}  // namespace mark
