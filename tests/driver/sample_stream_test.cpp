// The one streaming core of sample-level jobs (driver/sample_stream.hpp) and its one
// classification of endings (driver/stream_ending.hpp), on the simulated stylus head and the
// simulated scanner: a job to its end, an abort of the device from another thread (aborted, not
// a fault — the stylus's run used to call it one), an underrun, a producer that throws (the
// device's job is ended, the head lifted, the error goes on).
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>

#include "driver/sample_stream.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "driver/sim/sim_stylus_head.hpp"
#include "driver/sim/stylus_head_model.hpp"

namespace mark {
namespace {

DeviceReport report(DeviceState outcome, std::optional<DeviceFault> fault = {}) {
  DeviceReport r;
  r.outcome = outcome;
  r.fault = std::move(fault);
  return r;
}

DrainStats ended(DrainEnd end, std::uint64_t stop_sample = 0) {
  DrainStats d;
  d.end = end;
  d.stop_sample = stop_sample;
  return d;
}

TEST(StreamEnding, EveryDrainEndingHasOneJobEnding) {
  const DeviceFault own{FaultCategory::out_of_field, "sample 70 outside", 70};
  // Completed: done, or failed when the device kept a fault of its own.
  StreamEnding e = classify_ending(ended(DrainEnd::completed), nullptr, report(DeviceState::done), "laser off");
  EXPECT_EQ(e.outcome, DeviceState::done);
  EXPECT_FALSE(e.fault);
  EXPECT_EQ(e.stopped_at, 0u);
  e = classify_ending(ended(DrainEnd::completed), nullptr, report(DeviceState::failed, own), "laser off");
  EXPECT_EQ(e.outcome, DeviceState::failed);
  EXPECT_EQ(e.stopped_at, 70u);
  // Cancelled: aborted where the drain stopped.
  e = classify_ending(ended(DrainEnd::cancelled, 1200), nullptr, report(DeviceState::aborted), "laser off");
  EXPECT_EQ(e.outcome, DeviceState::aborted);
  EXPECT_FALSE(e.fault);
  EXPECT_EQ(e.stopped_at, 1200u);
  // Underrun: a fault of its own category, naming what the safe sample did.
  e = classify_ending(ended(DrainEnd::underrun, 555), nullptr, report(DeviceState::aborted), "stylus lifted");
  EXPECT_EQ(e.outcome, DeviceState::failed);
  ASSERT_TRUE(e.fault);
  EXPECT_EQ(e.fault->category, FaultCategory::underrun);
  EXPECT_EQ(e.fault->at, 555u);
  EXPECT_EQ(e.fault->message,
            "line memory underrun at sample 555: the producer fell behind the device's clock; stylus "
            "lifted for the rest of the job");
  EXPECT_EQ(e.stopped_at, 555u);
  // A device that threw: its fault, at its own index...
  const auto thrown = std::make_exception_ptr(DeviceFaultError(own));
  e = classify_ending(ended(DrainEnd::device_fault, 100), thrown, report(DeviceState::failed, own), "laser off");
  EXPECT_EQ(e.outcome, DeviceState::failed);
  EXPECT_EQ(e.fault->message, own.message);
  EXPECT_EQ(e.stopped_at, 70u);
  // ...unless it was aborted from outside and refused the next block: that is the abort.
  const auto refused = std::make_exception_ptr(
      DeviceStateError("sim SL10", "write", DeviceState::aborted, "the laser is halted until reset()"));
  e = classify_ending(ended(DrainEnd::device_fault, 300), refused, report(DeviceState::aborted), "laser off");
  EXPECT_EQ(e.outcome, DeviceState::aborted);
  EXPECT_FALSE(e.fault);
  EXPECT_EQ(e.stopped_at, 300u);
}

StreamOptions<StylusSample> stylus_stream(bool virtual_time) {
  StreamOptions<StylusSample> o;
  o.drain.rate_hz = kStylusRate_hz;
  o.drain.block_samples = 200;  // 1 ms
  o.drain.virtual_time = virtual_time;
  o.drain.realtime_priority = 0;
  o.drain.start_fill = 400;
  o.safe_state = "stylus lifted";
  return o;
}

JobHeader stylus_job(std::uint64_t samples) {
  JobHeader h;
  h.name = "stream";
  h.expected_samples = samples;
  return h;
}

// `n` samples 20 µm deep.
auto constant_drive(std::uint64_t n) {
  return [n, made = std::uint64_t{0}](std::span<StylusSample> out) mutable {
    const std::size_t k = static_cast<std::size_t>(std::min<std::uint64_t>(out.size(), n - made));
    for (std::size_t i = 0; i < k; ++i) out[i] = {20, false};
    made += k;
    return k;
  };
}

TEST(SampleStream, AStylusJobRunsToItsEndAndEndsLifted) {
  SimStylusHead head;
  const StreamResult r = stream_samples(head, stylus_job(10000), constant_drive(10000), stylus_stream(true));
  EXPECT_EQ(r.ending.outcome, DeviceState::done);
  EXPECT_EQ(r.produced, 10000u);
  EXPECT_EQ(r.drain.end, DrainEnd::completed);
  EXPECT_EQ(r.device.outcome, DeviceState::done);
  EXPECT_EQ(r.device.samples_out, 10001u);  // and the closing safe sample
  EXPECT_EQ(head.cut_profile_um().back(), 0.0f);  // the safe sample lifted it
  EXPECT_TRUE(head.lifted());
  EXPECT_GT(head.max_cut_um(), 15.0);
}

TEST(SampleStream, AnUnderrunFailsTheJobWithTheStylusLifted) {
  SimStylusHead head;
  StreamOptions<StylusSample> o = stylus_stream(true);
  o.drain.starve_at = 4321;
  const StreamResult r = stream_samples(head, stylus_job(10000), constant_drive(10000), o);
  EXPECT_EQ(r.ending.outcome, DeviceState::failed);
  ASSERT_TRUE(r.ending.fault);
  EXPECT_EQ(r.ending.fault->category, FaultCategory::underrun);
  EXPECT_EQ(r.ending.stopped_at, 4321u);
  EXPECT_NE(r.ending.fault->message.find("stylus lifted for the rest of the job"), std::string::npos);
  // Nothing cut after the missing sample.
  const auto& cut = head.cut_profile_um();
  for (std::size_t k = 4321; k < cut.size(); ++k) ASSERT_EQ(cut[k], 0.0f) << k;
}

TEST(SampleStream, AProducerThatThrowsEndsTheDevicesJobFirst) {
  SimStylusHead head;
  std::uint64_t made = 0;
  const auto failing = [&](std::span<StylusSample> out) -> std::size_t {
    if (made >= 3000) throw std::runtime_error("toolpath: cell 17 has no depth");
    for (StylusSample& s : out) s = {20, false};
    made += out.size();
    return out.size();
  };
  StreamOptions<StylusSample> o = stylus_stream(true);
  o.first_block = o.block = 1000;
  EXPECT_THROW(stream_samples(head, stylus_job(10000), failing, o), std::runtime_error);
  const DeviceStatus st = head.status();
  EXPECT_EQ(st.state, DeviceState::aborted);  // ended: the drain halted it, end_job was called
  EXPECT_TRUE(head.lifted());
  EXPECT_LE(head.samples(), 3001u);
  head.reset();  // and it is re-armable
  EXPECT_EQ(stream_samples(head, stylus_job(500), constant_drive(500), stylus_stream(true)).ending.outcome,
            DeviceState::done);
}

// A device aborted from another thread mid-job (a station's network thread) refuses its next
// block; the job ends aborted, within a block of the abort, never as a fault.
template <class T, class Device, class Make>
void abort_from_another_thread(Device& device, const JobHeader& header, StreamOptions<T> o, Make make,
                               std::uint64_t block) {
  std::atomic<std::uint64_t> at_abort{0};
  // The station waits for 20 blocks, or for the job to end first (a real-time job on an
  // overloaded machine can underrun before then): the test then fails instead of hanging.
  std::atomic<bool> ended{false};
  std::thread station([&] {
    while (device.status().progress < 20 * block && !ended.load())
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    if (ended.load()) return;
    device.abort();
    at_abort = device.status().progress;
  });
  const StreamResult r = stream_samples(device, header, make, o);
  ended.store(true);
  station.join();
  ASSERT_EQ(r.ending.outcome, DeviceState::aborted) << "the job ended before the abort";
  EXPECT_FALSE(r.ending.fault);
  EXPECT_EQ(r.device.outcome, DeviceState::aborted);
  EXPECT_LE(r.device.samples_out, at_abort + block);
  EXPECT_LE(r.ending.stopped_at, at_abort + block);
  EXPECT_GE(r.ending.stopped_at, 20 * block);
  EXPECT_FALSE(device.status().laser_on);
}

TEST(SampleStream, AnAbortFromAnotherThreadEndsTheStylusJobAborted) {
  SimStylusHead head;
  // 0.5 s of stylus time in real time: the abort lands mid-job.
  abort_from_another_thread<StylusSample>(head, stylus_job(100000), stylus_stream(false), constant_drive(100000), 200);
  EXPECT_TRUE(head.lifted());
}

TEST(SampleStream, AnAbortFromAnotherThreadEndsTheScannerJobAborted) {
  SimScanner scanner;
  JobHeader h;
  h.name = "stream";
  h.pens = {DevicePen{}};
  StreamOptions<ScanSample> o;
  o.drain.rate_hz = 1e5;
  o.drain.block_samples = 100;
  o.drain.realtime_priority = 0;
  o.drain.start_fill = 200;
  std::uint64_t made = 0;
  const auto circle = [&](std::span<ScanSample> out) -> std::size_t {  // 0.5 s round a 10 mm circle
    std::size_t k = 0;
    for (; k < out.size() && made < 50000; ++k, ++made) {
      const double a = 2e-4 * static_cast<double>(made);
      out[k] = {static_cast<float>(5 * std::cos(a)), static_cast<float>(5 * std::sin(a)), true, 255};
    }
    return k;
  };
  abort_from_another_thread<ScanSample>(scanner, h, o, circle, 100);
  EXPECT_EQ(scanner.laser_power(), 0.0);
}

}  // namespace
}  // namespace mark
