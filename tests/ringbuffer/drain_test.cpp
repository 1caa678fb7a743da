// The drain: fixed blocks in order; an underrun is a fault that puts the laser out for the rest of
// the job; a stop request is honoured within one block with a safe sample; every ending leaves
// the device on a safe sample; the delay line's tail is flushed; a device fault halts the device;
// injected starvation and stop points act at the exact sample; drain and memory are re-armable.
#include "ringbuffer/drain.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
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

// No lit sample at or after `from`.
void expect_dark_from(const std::vector<ScanSample>& samples, std::size_t from) {
  for (std::size_t i = from; i < samples.size(); ++i)
    ASSERT_FALSE(samples[i].laser) << "sample " << i << " is lit after the laser should be out";
}

TEST(Drain, VirtualTimeDeliversEverythingInFixedBlocksThenASafeSample) {
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  const auto in = ramp(1050);
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(in)));
  memory.close();
  Drain<ScanSample> drain(memory, sink, {.block_samples = 100, .virtual_time = true});
  drain.start();
  const DrainStats st = drain.join();
  ASSERT_EQ(sink.samples.size(), 1051u);
  for (std::size_t i = 0; i < in.size(); ++i) ASSERT_EQ(sink.samples[i].x_mm, in[i].x_mm);
  // The job ends on its safe sample: the last position, laser off.
  EXPECT_FALSE(sink.samples.back().laser);
  EXPECT_EQ(sink.samples.back().x_mm, 1049.0f);
  ASSERT_EQ(sink.block_sizes.size(), 12u);
  EXPECT_EQ(sink.block_sizes[10], 50u);  // the last block of the job is not padded
  EXPECT_EQ(sink.block_sizes[11], 1u);   // the safe sample
  EXPECT_EQ(st.samples_out, 1051u);
  EXPECT_EQ(st.end, DrainEnd::completed);
  EXPECT_EQ(st.underrun_events, 0u);
  EXPECT_EQ(st.peak_fill, 1050u);
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
  ASSERT_EQ(sink.samples.size(), 501u);
  for (std::size_t i = 0; i < 500; ++i) ASSERT_EQ(sink.samples[i].x_mm, static_cast<float>(i));
  EXPECT_EQ(st.end, DrainEnd::completed);
  EXPECT_EQ(st.underrun_events, 0u);
  for (std::size_t i = 0; i + 2 < sink.block_sizes.size(); ++i) EXPECT_EQ(sink.block_sizes[i], 10u);
}

TEST(Drain, RealTimeUnderrunPutsTheLaserOutForTheRestOfTheJob) {
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  // 100 kHz, 1 ms blocks. 150 samples, then the producer stalls: block 2 is half empty.
  Drain<ScanSample> drain(memory, sink, {.rate_hz = 100000, .block_samples = 100});
  const auto first = ramp(150), second = ramp(120, 150);
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(first)));
  drain.start();
  const DrainStats st = drain.join();  // the underrun ends the job on its own
  // The producer comes back too late: the memory refuses, nothing resumes.
  EXPECT_FALSE(memory.push(std::span<const ScanSample>(second)));

  EXPECT_EQ(st.end, DrainEnd::underrun);
  EXPECT_EQ(st.stop_sample, 150u);  // the first missing sample
  EXPECT_EQ(st.underrun_events, 1u);
  EXPECT_EQ(st.underrun_samples, 50u);
  ASSERT_EQ(sink.samples.size(), 200u);  // two full blocks: 150 real, 50 safe
  for (std::size_t i = 0; i < 150; ++i) ASSERT_TRUE(sink.samples[i].laser);
  expect_dark_from(sink.samples, 150);
  // The safe samples hold the last real position, where the producer stopped.
  EXPECT_EQ(sink.samples[150].x_mm, 149.0f);
  EXPECT_EQ(sink.samples[199].x_mm, 149.0f);
  EXPECT_TRUE(sink.halted);
  EXPECT_GE(st.lateness_max_us, st.lateness_p99_us);
  EXPECT_GE(st.lateness_p99_us, st.lateness_median_us);
}

TEST(Drain, InjectedStarvationIsAnUnderrunAtThatSampleInVirtualTimeToo) {
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  const auto in = ramp(1000);
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(in)));
  memory.close();
  Drain<ScanSample> drain(memory, sink, {.block_samples = 100, .virtual_time = true, .starve_at = 437});
  drain.start();
  const DrainStats st = drain.join();
  EXPECT_EQ(st.end, DrainEnd::underrun);
  EXPECT_EQ(st.stop_sample, 437u);
  ASSERT_EQ(sink.samples.size(), 500u);
  for (std::size_t i = 0; i < 437; ++i) ASSERT_TRUE(sink.samples[i].laser);
  expect_dark_from(sink.samples, 437);
  EXPECT_EQ(sink.samples.back().x_mm, 436.0f);
  EXPECT_TRUE(sink.halted);
}

TEST(Drain, StarvationPointAfterTheEndOfTheJobIsNoUnderrun) {
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  const auto in = ramp(300);
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(in)));
  memory.close();
  Drain<ScanSample> drain(memory, sink, {.block_samples = 100, .starve_at = 300});
  drain.start();
  const DrainStats st = drain.join();
  EXPECT_EQ(st.end, DrainEnd::completed);
  EXPECT_EQ(sink.samples.size(), 301u);
}

TEST(Drain, InjectedStopActsAtTheExactSampleWithASafeSample) {
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  const auto in = ramp(1000);
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(in)));
  memory.close();
  Drain<ScanSample> drain(memory, sink, {.block_samples = 100, .virtual_time = true, .stop_at = 321});
  drain.start();
  const DrainStats st = drain.join();
  EXPECT_EQ(st.end, DrainEnd::cancelled);
  EXPECT_EQ(st.stop_sample, 321u);
  ASSERT_EQ(sink.samples.size(), 322u);
  expect_dark_from(sink.samples, 321);
  EXPECT_EQ(sink.samples[321].x_mm, 320.0f);
  EXPECT_TRUE(sink.halted);
}

TEST(Drain, RealTimeWaitsForTheStartFillBeforeTheClockStarts) {
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  Drain<ScanSample> drain(memory, sink, {.block_samples = 50, .start_fill = 300});
  drain.start();
  // Trickle in 300 samples slowly: no block may go out before all are there, so no underrun.
  // The memory is closed right after the last part: once all 300 are in, the drain's clock runs
  // through them in 3 ms, and a producer that slept after its last push could lose the CPU for
  // that long on a loaded machine (an underrun of the test, not of the drain).
  for (std::size_t i = 0; i < 300; i += 30) {
    if (i > 0) std::this_thread::sleep_for(std::chrono::microseconds(500));
    const auto part = ramp(30, i);
    ASSERT_TRUE(memory.push(std::span<const ScanSample>(part)));
  }
  memory.close();
  const DrainStats st = drain.join();
  EXPECT_EQ(st.end, DrainEnd::completed);
  EXPECT_EQ(sink.samples.size(), 301u);
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
  // 7 delayed-off ticks lit + the off sample of the delay line, then the drain's safe sample.
  ASSERT_EQ(sink.samples.size(), 205u + 8u + 1u);
  EXPECT_FALSE(sink.samples[0].laser);
  EXPECT_FALSE(sink.samples[1].laser);
  EXPECT_TRUE(sink.samples[2].laser);
  EXPECT_TRUE(sink.samples[211].laser);
  EXPECT_FALSE(sink.samples[212].laser);
  EXPECT_FALSE(sink.samples.back().laser);
  EXPECT_EQ(sink.samples.back().x_mm, 204.0f);
  EXPECT_EQ(st.samples_out, 214u);
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

TEST(Drain, StopRequestPutsTheLaserOutWithinOneBlockOfTheRequest) {
  // A long lit job in real time; a stop is requested from another thread at an arbitrary moment.
  // The drain checks after every wait, so the device gets at most one block after the request
  // fell on its clock (measured by the drain on the device's own sample clock), then a safe
  // sample, then halt.
  for (const std::size_t block : {100u, 37u}) {
    LineMemory<ScanSample> memory(1 << 16);
    RecordingSink<ScanSample> sink;
    StopFlag stop;
    Drain<ScanSample> drain(memory, sink, {.block_samples = block, .stop = &stop});
    const auto in = ramp(50000);  // 0.5 s of samples, never closed
    ASSERT_TRUE(memory.push(std::span<const ScanSample>(in)));
    drain.start();
    while (drain.samples_out() < 1234) std::this_thread::sleep_for(std::chrono::microseconds(130));
    stop.request();
    const std::int64_t published_ns = StopFlag::now_ns();
    const DrainStats st = drain.join();
    EXPECT_EQ(st.end, DrainEnd::cancelled);
    EXPECT_TRUE(sink.halted);
    EXPECT_GE(st.stop_sample, 1234u);
    // The request's time is taken before its flag is published; a preemption in between (seen
    // under ThreadSanitizer on a loaded machine) is time the drain could not have seen it.
    const double publish_gap_samples =
        static_cast<double>(published_ns - stop.requested_at_ns()) * 1e-9 * DrainOptions{}.rate_hz;
    EXPECT_LE(static_cast<double>(st.stop_latency_samples),
              static_cast<double>(block) + std::ceil(publish_gap_samples))
        << "block " << block << ", publishing took " << publish_gap_samples << " samples";
    EXPECT_GE(st.stop_latency_us, 0.0);
    ASSERT_EQ(sink.samples.size(), st.stop_sample + 1);
    EXPECT_EQ(st.stop_sample % block, 0u);  // stopped at a block boundary, not mid-block
    expect_dark_from(sink.samples, st.stop_sample);
  }
}

TEST(Drain, StopRequestedBeforeTheFirstSampleSendsOnlyTheSafeSample) {
  LineMemory<ScanSample> memory(1024);
  RecordingSink<ScanSample> sink;
  StopFlag stop;
  stop.request();
  Drain<ScanSample> drain(memory, sink, {.block_samples = 100, .stop = &stop});
  const auto in = ramp(500);
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(in)));
  drain.start();
  const DrainStats st = drain.join();
  EXPECT_EQ(st.end, DrainEnd::cancelled);
  EXPECT_EQ(st.stop_sample, 0u);
  ASSERT_EQ(sink.samples.size(), 1u);
  EXPECT_FALSE(sink.samples[0].laser);
}

TEST(Drain, DrainAndMemoryRunASecondJobAfterAnUnderrun) {
  // A station runs for months: after a faulted job, reset the memory and start the drain again.
  LineMemory<ScanSample> memory(4096);
  RecordingSink<ScanSample> sink;
  Drain<ScanSample> drain(memory, sink, {.block_samples = 100, .virtual_time = true, .starve_at = 50});
  const auto job = ramp(120);
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(job)));
  memory.close();
  drain.start();
  EXPECT_EQ(drain.join().end, DrainEnd::underrun);
  EXPECT_FALSE(memory.push(job[0]));  // aborted until reset

  memory.reset();
  sink = RecordingSink<ScanSample>();
  Drain<ScanSample> next(memory, sink, {.block_samples = 100, .virtual_time = true});
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(job)));
  memory.close();
  next.start();
  const DrainStats st = next.join();
  EXPECT_EQ(st.end, DrainEnd::completed);
  EXPECT_EQ(st.samples_out, 121u);
  EXPECT_EQ(memory.pushed(), 120u);

  // The same drain object re-arms too.
  memory.reset();
  sink = RecordingSink<ScanSample>();
  ASSERT_TRUE(memory.push(std::span<const ScanSample>(job)));
  memory.close();
  next.start();
  EXPECT_EQ(next.join().samples_out, 121u);
  EXPECT_EQ(sink.samples.size(), 121u);
}

TEST(Drain, SafeScanSampleHoldsThePositionWithTheLaserOff) {
  const ScanSample h = safe_sample(lit_at(3, 4));
  EXPECT_FALSE(h.laser);
  EXPECT_EQ(h.x_mm, 3.0f);
  EXPECT_EQ(h.y_mm, 4.0f);
}

}  // namespace
}  // namespace mark
