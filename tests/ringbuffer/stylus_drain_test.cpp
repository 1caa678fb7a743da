// The gravure stylus through the same line memory and fixed-rate drain as the laser: samples
// arrive in order and in fixed blocks, and every ending — the end of the job, a stop request,
// an underrun — leaves the stylus on its safe sample, lifted clear of the cylinder, never on
// the last depth (which would keep cutting).
#include <gtest/gtest.h>

#include <thread>

#include "ringbuffer/drain.hpp"
#include "ringbuffer/stylus_sample.hpp"
#include "tests/ringbuffer/recording_sink.hpp"

namespace mark {
namespace {

using test::RecordingSink;

static_assert(HasSafeSample<StylusSample>);

TEST(StylusDrain, DeliversEverySampleInOrderAtTheStylusClock) {
  LineMemory<StylusSample> memory(4096);
  RecordingSink<StylusSample> sink;
  std::vector<StylusSample> in(2500);
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = {static_cast<float>(i % 40), false};
  ASSERT_TRUE(memory.push(std::span<const StylusSample>(in)));
  memory.close();
  Drain<StylusSample> drain(memory, sink, {.rate_hz = 200000, .block_samples = 1000, .virtual_time = true});
  drain.start();
  const DrainStats st = drain.join();
  ASSERT_EQ(sink.samples.size(), in.size() + 1);
  for (std::size_t i = 0; i < in.size(); ++i) ASSERT_EQ(sink.samples[i].drive_um, in[i].drive_um);
  EXPECT_EQ(sink.block_sizes, (std::vector<std::size_t>{1000, 1000, 500, 1}));
  EXPECT_EQ(st.underrun_events, 0u);
  EXPECT_EQ(st.end, DrainEnd::completed);
}

TEST(StylusDrain, TheJobEndsOnTheLiftedSafeSample) {
  LineMemory<StylusSample> memory(64);
  RecordingSink<StylusSample> sink;
  const std::vector<StylusSample> deep(50, StylusSample{35, false});
  ASSERT_TRUE(memory.push(std::span<const StylusSample>(deep)));
  memory.close();
  Drain<StylusSample> drain(memory, sink, {.rate_hz = 200000, .block_samples = 20, .virtual_time = true});
  drain.start();
  drain.join();
  ASSERT_EQ(sink.samples.size(), 51u);
  EXPECT_TRUE(sink.samples.back().lifted);
  EXPECT_EQ(sink.samples.back().drive_um, kStylusSafeDrive_um);
}

TEST(StylusDrain, AStopRequestLiftsTheStylusWithinOneBlock) {
  LineMemory<StylusSample> memory(1 << 12);
  RecordingSink<StylusSample> sink;
  StopFlag stop;
  Drain<StylusSample> drain(memory, sink, {.rate_hz = 200000, .block_samples = 200, .virtual_time = false, .stop = &stop});
  const std::vector<StylusSample> deep(4000, StylusSample{35, false});
  ASSERT_TRUE(memory.push(std::span<const StylusSample>(deep)));
  drain.start();
  std::this_thread::sleep_for(std::chrono::milliseconds(3));
  stop.request();
  const DrainStats st = drain.join();
  EXPECT_EQ(st.end, DrainEnd::cancelled);
  ASSERT_LT(sink.samples.size(), 4000u);
  EXPECT_TRUE(sink.samples.back().lifted);
  EXPECT_TRUE(sink.halted);
  for (std::size_t i = 0; i + 1 < sink.samples.size(); ++i) ASSERT_FALSE(sink.samples[i].lifted);
}

TEST(StylusDrain, UnderrunSendsTheLiftedStylusNotTheLastDepth) {
  LineMemory<StylusSample> memory(1 << 16);
  RecordingSink<StylusSample> sink;
  // Real time at 200 kHz, 1 ms blocks; the producer gives 3 blocks deep in the copper, then
  // stalls for 20 ms: an underrun, a fault that ends the job with the stylus lifted.
  Drain<StylusSample> drain(memory, sink, {.rate_hz = 200000, .block_samples = 200, .virtual_time = false});
  const std::vector<StylusSample> deep(600, StylusSample{35, false});
  ASSERT_TRUE(memory.push(std::span<const StylusSample>(deep)));
  drain.start();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  memory.close();
  const DrainStats st = drain.join();
  EXPECT_EQ(st.end, DrainEnd::underrun);
  EXPECT_EQ(st.underrun_events, 1u);
  EXPECT_EQ(st.stop_sample, 600u);
  EXPECT_TRUE(sink.halted);
  ASSERT_EQ(sink.samples.size(), 800u);  // the starved fourth block, padded
  for (std::size_t i = 0; i < 600; ++i) ASSERT_EQ(sink.samples[i].drive_um, 35);
  for (std::size_t i = 600; i < sink.samples.size(); ++i) {
    ASSERT_TRUE(sink.samples[i].lifted) << i;
    ASSERT_EQ(sink.samples[i].drive_um, kStylusSafeDrive_um) << i;
    ASSERT_LT(sink.samples[i].drive_um, 0) << i;  // above the surface, not the last 35 µm
  }
}

TEST(StylusDrain, AbortHaltsTheDevice) {
  LineMemory<StylusSample> memory(256);
  RecordingSink<StylusSample> sink;
  Drain<StylusSample> drain(memory, sink, {.rate_hz = 200000, .block_samples = 100, .virtual_time = true});
  drain.start();
  const std::vector<StylusSample> deep(100, StylusSample{20, false});
  ASSERT_TRUE(memory.push(std::span<const StylusSample>(deep)));
  drain.abort();
  const DrainStats st = drain.join();
  EXPECT_EQ(st.end, DrainEnd::cancelled);
  EXPECT_TRUE(sink.halted);
  ASSERT_FALSE(sink.samples.empty());
  EXPECT_TRUE(sink.samples.back().lifted);
}

}  // namespace
}  // namespace mark
