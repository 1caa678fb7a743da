// The drain: fixed blocks in order, underrun holds with the laser off at the last position,
// virtual time that waits instead of underrunning, end-of-job flush of the delay line, halting
// the device on abort and on a device fault.
#include "ringbuffer/drain.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "ringbuffer/laser_delay_line.hpp"
#include "ringbuffer/scan_sample.hpp"
#include "tests/ringbuffer/recording_sink.hpp"

namespace mark {
namespace {

using test::RecordingSink;

ScanSample lit_at(float x, float y) { return ScanSample{x, y, true, 200}; }

std::vector<ScanSample> ramp(std::size_t n, std::size_t first = 0) {
  std::vector<ScanSample> s(n);
  for (std::size_t i = 0; i < n; ++i) s[i] = lit_at(static_cast<float>(first + i), 1.0f);
  return s;
}

TEST(Drain, VirtualTimeDeliversEverythingInFixedBlocks) {
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  const auto in = ramp(1050);
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(in)));
  memory.close();
  Drain<ScanSample> drain(memory, sink, {.block_samples = 100, .virtual_time = true});
  drain.start();
  const DrainStats st = drain.join();
  ASSERT_EQ(sink.samples.size(), 1050u);
  for (std::size_t i = 0; i < in.size(); ++i) ASSERT_EQ(sink.samples[i].x_mm, in[i].x_mm);
  EXPECT_EQ(sink.block_sizes.size(), 11u);
  EXPECT_EQ(sink.block_sizes.back(), 50u);  // the last block is not padded
  EXPECT_EQ(st.samples_out, 1050u);
  EXPECT_EQ(st.blocks, 11u);
  EXPECT_EQ(st.underrun_events, 0u);
  EXPECT_EQ(st.peak_fill, 1050u);
  EXPECT_FALSE(st.aborted);
  EXPECT_FALSE(sink.halted);
}

TEST(Drain, VirtualTimeWaitsForASlowProducerWithoutUnderrun) {
  LineMemory<ScanSample> memory(16);
  RecordingSink<ScanSample> sink;
  Drain<ScanSample> drain(memory, sink, {.block_samples = 10, .virtual_time = true});
  drain.start();
  for (std::size_t i = 0; i < 500; ++i) {
    ASSERT_TRUE(memory.push(lit_at(static_cast<float>(i), 0)));
    if (i % 37 == 0) std::this_thread::sleep_for(std::chrono::microseconds(300));
  }
  memory.close();
  const DrainStats st = drain.join();
  ASSERT_EQ(sink.samples.size(), 500u);
  for (std::size_t i = 0; i < 500; ++i) ASSERT_EQ(sink.samples[i].x_mm, static_cast<float>(i));
  EXPECT_EQ(st.underrun_events, 0u);
  EXPECT_EQ(st.underrun_samples, 0u);
  for (std::size_t i = 0; i + 1 < sink.block_sizes.size(); ++i) EXPECT_EQ(sink.block_sizes[i], 10u);
}

TEST(Drain, RealTimeUnderrunHoldsTheLastPositionWithTheLaserOff) {
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  // 100 kHz, 1 ms blocks. 150 samples, then the producer stalls for ≥ 3 blocks.
  Drain<ScanSample> drain(memory, sink, {.rate_hz = 100000, .block_samples = 100});
  const auto first = ramp(150), second = ramp(120, 150);
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(first)));
  drain.start();
  while (drain.samples_out() < 500) std::this_thread::sleep_for(std::chrono::microseconds(200));
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(second)));
  memory.close();
  const DrainStats st = drain.join();

  // Every real sample arrives, in order; everything else is a hold sample: the last real
  // position before it, laser off.
  std::size_t real = 0, holds = 0;
  ScanSample last{};
  for (const ScanSample& s : sink.samples) {
    if (real < 270 && s.laser && s.x_mm == static_cast<float>(real)) {
      last = s;
      ++real;
      continue;
    }
    ++holds;
    EXPECT_FALSE(s.laser);
    EXPECT_EQ(s.x_mm, last.x_mm);
    EXPECT_EQ(s.y_mm, last.y_mm);
  }
  EXPECT_EQ(real, 270u);
  EXPECT_GE(holds, 350u);  // block 2 half empty, then ≥ 3 empty blocks
  EXPECT_EQ(st.underrun_samples, holds);
  EXPECT_GE(st.underrun_events, 1u);
  EXPECT_EQ(st.samples_out, sink.samples.size());
  // The hold right after the stall sits at sample 149, where the producer stopped.
  EXPECT_FALSE(sink.samples[150].laser);
  EXPECT_EQ(sink.samples[150].x_mm, 149.0f);
  // Blocks are always full in real time except the very last one.
  for (std::size_t i = 0; i + 1 < sink.block_sizes.size(); ++i) EXPECT_EQ(sink.block_sizes[i], 100u);
  EXPECT_GE(st.lateness_max_us, st.lateness_p99_us);
  EXPECT_GE(st.lateness_p99_us, st.lateness_median_us);
}

TEST(Drain, RealTimeWaitsForTheStartFillBeforeTheClockStarts) {
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  Drain<ScanSample> drain(memory, sink, {.block_samples = 50, .start_fill = 300});
  drain.start();
  // Trickle in 300 samples slowly: no block may go out before all are there, so no underrun.
  for (std::size_t i = 0; i < 300; i += 30) {
    const auto part = ramp(30, i);
    ASSERT_TRUE(memory.push(std::span<const ScanSample>(part)));
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
  memory.close();
  const DrainStats st = drain.join();
  EXPECT_EQ(st.underrun_samples, 0u);
  EXPECT_EQ(sink.samples.size(), 300u);
}

TEST(Drain, FlushesTheDelayLineSoTheJobEndsDark) {
  LineMemory<ScanSample> memory(1024);
  RecordingSink<ScanSample> sink;
  LaserDelayLine delay(2, 7);
  const auto in = ramp(205);  // lit to the very end
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(in)));
  memory.close();
  Drain<ScanSample> drain(memory, sink, {.block_samples = 100, .virtual_time = true}, &delay);
  drain.start();
  const DrainStats st = drain.join();
  ASSERT_EQ(sink.samples.size(), 205u + 8u);  // 7 delayed-off ticks lit + the off sample
  EXPECT_FALSE(sink.samples[0].laser);
  EXPECT_FALSE(sink.samples[1].laser);
  EXPECT_TRUE(sink.samples[2].laser);
  EXPECT_TRUE(sink.samples[211].laser);
  EXPECT_FALSE(sink.samples.back().laser);
  EXPECT_EQ(sink.samples.back().x_mm, 204.0f);
  EXPECT_EQ(st.samples_out, 213u);
}

TEST(Drain, SinkFaultHaltsTheDeviceReleasesTheProducerAndRethrows) {
  LineMemory<ScanSample> memory(64);
  RecordingSink<ScanSample> sink;
  sink.fail_at_block = 3;
  Drain<ScanSample> drain(memory, sink, {.block_samples = 10, .virtual_time = true});
  drain.start();
  std::vector<ScanSample> many = ramp(100000);
  EXPECT_FALSE(memory.push(std::span<const ScanSample>(many)));  // released by the abort
  EXPECT_THROW(
      {
        try {
          drain.join();
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "device fault at block 3");
          throw;
        }
      },
      std::runtime_error);
  EXPECT_TRUE(sink.halted);
  EXPECT_EQ(sink.samples.size(), 30u);
}

TEST(Drain, AbortHaltsTheDeviceAndStops) {
  LineMemory<ScanSample> memory(1 << 16);
  RecordingSink<ScanSample> sink;
  Drain<ScanSample> drain(memory, sink, {.block_samples = 100});
  const auto in = ramp(20000);  // 200 ms of samples, never closed
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(in)));
  drain.start();
  while (drain.samples_out() < 300) std::this_thread::sleep_for(std::chrono::microseconds(200));
  drain.abort();
  const DrainStats st = drain.join();
  EXPECT_TRUE(st.aborted);
  EXPECT_TRUE(sink.halted);
  EXPECT_LT(sink.samples.size(), 20000u);
}

TEST(Drain, SafeScanSampleHoldsThePositionWithTheLaserOff) {
  const ScanSample h = safe_sample(lit_at(3, 4));
  EXPECT_FALSE(h.laser);
  EXPECT_EQ(h.x_mm, 3.0f);
  EXPECT_EQ(h.y_mm, 4.0f);
}

}  // namespace
}  // namespace mark
