#pragma once
// The one lifecycle of driver/device.hpp, asserted the same way on every device: a typed test
// suite over benches, each holding one device and what it takes to feed it and to see its
// laser from outside (the simulated scanner's beam power, the stylus's lift, the emulated
// board's laser port and emission, the laser bit of the last port write in a capture).
//
// A bench B provides:
//   static std::string name();                  readable test names ("SimScanner", "LmcEmulated")
//   Device& device();
//   JobHeader header();                         a job of up to kMaxPieces pieces
//   void feed(std::size_t k);                   piece k of that job: a block of samples or a chunk
//                                               of commands, lit; throws what the device throws
//   void feed_outside(std::size_t k);           piece k with a point outside the device's field
//                                               (a drive outside the amplifier's range): the
//                                               device refuses it with DeviceFaultError
//   std::uint64_t units(std::size_t pieces);    status().progress after that many pieces, done
//   std::uint64_t stop_bound();                 progress a device may still make after abort()
//                                               returns: the block the drain is writing (samples)
//                                               or the list packet on the wire (commands)
//   bool laser_off();                           seen from outside the device, once nothing feeds
//                                               it; kSeesLaserWhileFed: also while a thread does
//                                               (a board's port, the stylus's lift — not the
//                                               simulated beam, which the drain thread owns)
//   double half_field_mm();                     where status().position may be
// The suite runs in driver_tests (simulated scanner, stylus head, LMC on the in-process emulated
// board, LMC to a capture file) and in lmc_usb_tests (LMC through libusb and umockdev).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>

#include "driver/device.hpp"

namespace mark::test {

inline constexpr std::size_t kJobPieces = 6;     // a short job
inline constexpr std::size_t kMaxPieces = 400;   // the longest job a bench's header allows

// A producer on its own thread hands over its pieces about as a drain would (blocks of about a
// millisecond), so the other thread meets the job in the middle, also on a loaded machine.
inline void pace() { std::this_thread::sleep_for(std::chrono::microseconds(200)); }

// Readable parameterised names: the bench's own, not a type dump.
struct BenchName {
  template <class B>
  static std::string GetName(int) {
    return B::name();
  }
};

template <class B>
class DeviceLifecycle : public ::testing::Test {
 protected:
  B bench;
  Device& dev() { return bench.device(); }

  void run_job(std::size_t pieces = kJobPieces) {
    dev().begin_job(bench.header());
    for (std::size_t k = 0; k < pieces; ++k) bench.feed(k);
  }
  DeviceReport run_to_done(std::size_t pieces = kJobPieces) {
    run_job(pieces);
    return dev().end_job();
  }
  // A job ended by abort() after two pieces; feeding the rest executes nothing.
  DeviceReport run_aborted() {
    run_job(2);
    dev().abort();
    feed_after_stop(2, 4);
    return dev().end_job();
  }
  // A job ended by a fault in its third piece.
  DeviceReport run_failed() {
    run_job(2);
    EXPECT_THROW(bench.feed_outside(2), DeviceFaultError);
    return dev().end_job();
  }
  // Pieces fed after the job stopped: a sample device refuses each (DeviceStateError), a board
  // takes nothing more; neither executes any of it.
  void feed_after_stop(std::size_t from, std::size_t to) {
    const std::uint64_t before = dev().status().progress;
    for (std::size_t k = from; k < to; ++k) {
      try {
        bench.feed(k);
      } catch (const DeviceStateError&) {
      }
    }
    EXPECT_EQ(dev().status().progress, before) << "work was executed after the job stopped";
  }
  // The call refused with DeviceStateError naming the device, the call and the state.
  template <class F>
  void expect_refused(F&& call, const std::string& name, DeviceState state) {
    try {
      call();
      ADD_FAILURE() << name << " while " << to_string(state) << " was not refused";
    } catch (const DeviceStateError& e) {
      const std::string m = e.what();
      EXPECT_EQ(e.call(), name);
      EXPECT_EQ(e.state(), state);
      EXPECT_EQ(e.device(), dev().describe().name);
      EXPECT_NE(m.find(dev().describe().name + ": " + name + " while " + std::string(to_string(state))),
                std::string::npos)
          << m;
    }
  }
  void expect_state(DeviceState want) {
    const DeviceStatus st = dev().status();
    EXPECT_EQ(st.state, want) << "is " << to_string(st.state);
  }
  void bring_to(DeviceState s) {
    switch (s) {
      case DeviceState::idle: break;
      case DeviceState::running: dev().begin_job(bench.header()); break;
      case DeviceState::done: run_to_done(); break;
      case DeviceState::aborted: run_aborted(); break;
      case DeviceState::failed: run_failed(); break;
    }
    expect_state(s);
  }
};

TYPED_TEST_SUITE_P(DeviceLifecycle);

TYPED_TEST_P(DeviceLifecycle, StartsIdleWithTheLaserOff) {
  const DeviceStatus st = this->dev().status();
  EXPECT_EQ(st.state, DeviceState::idle);
  EXPECT_FALSE(st.laser_on);
  EXPECT_FALSE(st.fault);
  EXPECT_EQ(st.progress, 0u);
  EXPECT_TRUE(this->bench.laser_off());
}

TYPED_TEST_P(DeviceLifecycle, AJobRunsFromIdleToDone) {
  this->dev().begin_job(this->bench.header());
  this->expect_state(DeviceState::running);
  for (std::size_t k = 0; k < kJobPieces; ++k) this->bench.feed(k);
  const DeviceReport r = this->dev().end_job();
  EXPECT_EQ(r.outcome, DeviceState::done);
  EXPECT_FALSE(r.fault);
  this->expect_state(DeviceState::done);
  EXPECT_EQ(this->dev().status().progress, this->bench.units(kJobPieces));
  EXPECT_TRUE(this->bench.laser_off());
  // end_job again: the same ending.
  EXPECT_EQ(this->dev().end_job().outcome, DeviceState::done);
}

TYPED_TEST_P(DeviceLifecycle, BeginJobOnlyFromIdle) {
  for (DeviceState s : {DeviceState::running, DeviceState::done, DeviceState::aborted, DeviceState::failed}) {
    SCOPED_TRACE(to_string(s));
    this->bring_to(s);
    const std::optional<DeviceFault> fault = this->dev().status().fault;
    this->expect_refused([&] { this->dev().begin_job(this->bench.header()); }, "begin_job", s);
    this->expect_state(s);  // nothing changed, not even the fault
    EXPECT_EQ(this->dev().status().fault.has_value(), fault.has_value());
    if (s == DeviceState::running) {
      // The refused begin_job left the running job alone: it still runs to its end.
      for (std::size_t k = 0; k < kJobPieces; ++k) this->bench.feed(k);
      EXPECT_EQ(this->dev().end_job().outcome, DeviceState::done);
    }
    this->dev().reset();
    this->expect_state(DeviceState::idle);
  }
}

TYPED_TEST_P(DeviceLifecycle, EndJobWithoutAJobIsRefused) {
  this->expect_refused([&] { this->dev().end_job(); }, "end_job", DeviceState::idle);
  this->expect_state(DeviceState::idle);
}

TYPED_TEST_P(DeviceLifecycle, ResetWhileRunningIsRefused) {
  this->run_job(2);
  this->expect_refused([&] { this->dev().reset(); }, "reset", DeviceState::running);
  this->expect_state(DeviceState::running);
  for (std::size_t k = 2; k < kJobPieces; ++k) this->bench.feed(k);
  EXPECT_EQ(this->dev().end_job().outcome, DeviceState::done);
  EXPECT_EQ(this->dev().status().progress, this->bench.units(kJobPieces));
}

TYPED_TEST_P(DeviceLifecycle, ResetFromEveryFinalStateGoesIdleAndIdleStaysIdle) {
  this->dev().reset();
  this->expect_state(DeviceState::idle);
  for (DeviceState s : {DeviceState::done, DeviceState::aborted, DeviceState::failed}) {
    SCOPED_TRACE(to_string(s));
    this->bring_to(s);
    this->dev().reset();
    const DeviceStatus st = this->dev().status();
    EXPECT_EQ(st.state, DeviceState::idle);
    EXPECT_FALSE(st.fault);  // cleared
    EXPECT_TRUE(this->bench.laser_off());
    this->dev().reset();  // idle stays idle
    this->expect_state(DeviceState::idle);
  }
}

TYPED_TEST_P(DeviceLifecycle, AbortWhileIdleKeepsTheLaserOffUntilReset) {
  this->dev().abort();
  this->expect_state(DeviceState::aborted);
  EXPECT_TRUE(this->bench.laser_off());
  EXPECT_FALSE(this->dev().status().laser_on);
  // No job starts on an aborted device: the operator's stop holds until reset.
  this->expect_refused([&] { this->dev().begin_job(this->bench.header()); }, "begin_job", DeviceState::aborted);
  this->dev().reset();
  this->expect_state(DeviceState::idle);
  // The next job runs whole: the abort before it does not leak into it.
  const DeviceReport r = this->run_to_done();
  EXPECT_EQ(r.outcome, DeviceState::done) << (r.fault ? r.fault->message : "");
  EXPECT_EQ(this->dev().status().progress, this->bench.units(kJobPieces));
}

TYPED_TEST_P(DeviceLifecycle, AbortWhileRunningEndsTheJobAborted) {
  this->run_job(2);
  const std::uint64_t at = this->dev().status().progress;
  this->dev().abort();
  this->expect_state(DeviceState::aborted);  // at once, before end_job
  EXPECT_FALSE(this->dev().status().laser_on);
  this->feed_after_stop(2, kJobPieces);
  const DeviceReport r = this->dev().end_job();
  EXPECT_EQ(r.outcome, DeviceState::aborted);
  EXPECT_FALSE(r.fault);
  EXPECT_EQ(this->dev().status().progress, at);
  EXPECT_TRUE(this->bench.laser_off());
}

TYPED_TEST_P(DeviceLifecycle, AbortFromAFinalStateChangesNothing) {
  for (DeviceState s : {DeviceState::done, DeviceState::aborted, DeviceState::failed}) {
    SCOPED_TRACE(to_string(s));
    this->bring_to(s);
    const std::optional<DeviceFault> fault = this->dev().status().fault;
    this->dev().abort();
    this->dev().abort();  // idempotent
    this->expect_state(s);
    const DeviceStatus st = this->dev().status();
    ASSERT_EQ(st.fault.has_value(), fault.has_value());
    if (fault) {
      EXPECT_EQ(st.fault->message, fault->message);  // a failed job keeps its fault
    }
    EXPECT_TRUE(this->bench.laser_off());
    EXPECT_EQ(this->dev().end_job().outcome, s);
    this->dev().reset();
  }
}

TYPED_TEST_P(DeviceLifecycle, AFaultFailsTheJobUntilReset) {
  this->run_job(2);
  const std::uint64_t at = this->dev().status().progress;
  DeviceFault thrown;
  try {
    this->bench.feed_outside(2);
    FAIL() << "the point outside the field was taken";
  } catch (const DeviceFaultError& e) {
    thrown = e.fault();
  }
  EXPECT_EQ(thrown.category, FaultCategory::out_of_field);
  const DeviceStatus st = this->dev().status();
  EXPECT_EQ(st.state, DeviceState::failed);
  ASSERT_TRUE(st.fault);
  EXPECT_EQ(st.fault->category, FaultCategory::out_of_field);
  EXPECT_FALSE(st.laser_on);
  EXPECT_EQ(st.progress, at);  // the refused piece was not executed
  // Nothing more is executed; feeding a failed job throws its fault or refuses.
  for (std::size_t k = 3; k < kJobPieces; ++k) EXPECT_THROW(this->bench.feed(k), DeviceError);
  EXPECT_EQ(this->dev().status().progress, at);
  const DeviceReport r = this->dev().end_job();
  EXPECT_EQ(r.outcome, DeviceState::failed);
  ASSERT_TRUE(r.fault);
  EXPECT_EQ(r.fault->message, st.fault->message);
  EXPECT_TRUE(this->bench.laser_off());
  this->dev().reset();
  this->expect_state(DeviceState::idle);
  EXPECT_EQ(this->run_to_done().outcome, DeviceState::done);
}

TYPED_TEST_P(DeviceLifecycle, FeedingAnEndedJobIsRefused) {
  this->run_to_done();
  try {
    this->bench.feed(0);
    ADD_FAILURE() << "work taken after the job ended";
  } catch (const DeviceStateError& e) {
    EXPECT_EQ(e.state(), DeviceState::done);
    EXPECT_EQ(e.device(), this->dev().describe().name);
  }
  this->expect_state(DeviceState::done);
}

TYPED_TEST_P(DeviceLifecycle, AbortFromAnotherThreadStopsWithinOneBlock) {
  this->dev().begin_job(this->bench.header());
  std::atomic<bool> fed_all{false};
  std::thread producer([&] {
    try {
      for (std::size_t k = 0; k < kMaxPieces; ++k) {
        this->bench.feed(k);
        pace();
      }
      fed_all = true;
    } catch (const DeviceStateError&) {
      // A sample device refuses the next block once aborted: the drain would stop here.
    } catch (const std::exception& e) {
      ADD_FAILURE() << "after abort() the device threw another type: " << e.what();
    }
  });
  // Mid-job: some pieces executed, the job far from its end.
  const std::uint64_t some = this->bench.units(3);
  for (int i = 0; i < 20000 && this->dev().status().progress < some; ++i)
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  this->dev().abort();
  const std::uint64_t at_abort = this->dev().status().progress;
  EXPECT_EQ(this->dev().status().state, DeviceState::aborted);
  if constexpr (TypeParam::kSeesLaserWhileFed) {
    EXPECT_TRUE(this->bench.laser_off()) << "when abort() returned";
  }
  producer.join();
  const std::uint64_t after = this->dev().status().progress;
  EXPECT_GE(at_abort, some);
  EXPECT_LT(at_abort, this->bench.units(kMaxPieces)) << "the job ended before the abort";
  EXPECT_LE(after - at_abort, this->bench.stop_bound()) << "executed after abort() returned";
  const DeviceReport r = this->dev().end_job();
  EXPECT_EQ(r.outcome, DeviceState::aborted);
  EXPECT_FALSE(r.fault);
  EXPECT_TRUE(this->bench.laser_off());
  this->RecordProperty("executed_after_abort", static_cast<int>(after - at_abort));
  (void)fed_all;
}

TYPED_TEST_P(DeviceLifecycle, StatusDuringAJobFromAnotherThread) {
  this->dev().begin_job(this->bench.header());
  const std::size_t pieces = kMaxPieces / 4;
  std::atomic<bool> finished{false};
  std::thread producer([&] {
    try {
      for (std::size_t k = 0; k < pieces; ++k) {
        this->bench.feed(k);
        pace();
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
    finished = true;
  });
  std::uint64_t last = 0, snapshots = 0;
  bool moved = false;
  while (!finished.load()) {
    const DeviceStatus st = this->dev().status();
    ++snapshots;
    EXPECT_EQ(st.state, DeviceState::running);
    EXPECT_GE(st.progress, last);
    EXPECT_LE(st.progress, this->bench.units(pieces));
    EXPECT_LE(std::abs(st.position.x), this->bench.half_field_mm() + 1e-3);
    EXPECT_LE(std::abs(st.position.y), this->bench.half_field_mm() + 1e-3);
    EXPECT_FALSE(st.fault);
    moved = moved || st.progress > 0;
    last = st.progress;
  }
  producer.join();
  EXPECT_GT(snapshots, 10u);
  EXPECT_TRUE(moved);
  EXPECT_EQ(this->dev().end_job().outcome, DeviceState::done);
  EXPECT_EQ(this->dev().status().progress, this->bench.units(pieces));
  this->expect_state(DeviceState::done);
}

TYPED_TEST_P(DeviceLifecycle, HundredJobsInARowReArm) {
  int done = 0, aborted = 0, failed = 0;
  for (int i = 0; i < 100; ++i) {
    SCOPED_TRACE(i);
    // Every third job stopped, every fifth failed, the rest marked to the end: each ending is
    // followed by a reset and the next job starts clean.
    if (i % 5 == 4) {
      const DeviceReport r = this->run_failed();
      EXPECT_EQ(r.outcome, DeviceState::failed);
      failed += r.outcome == DeviceState::failed;
    } else if (i % 3 == 2) {
      const DeviceReport r = this->run_aborted();
      EXPECT_EQ(r.outcome, DeviceState::aborted);
      aborted += r.outcome == DeviceState::aborted;
    } else {
      const DeviceReport r = this->run_to_done();
      EXPECT_EQ(r.outcome, DeviceState::done) << (r.fault ? r.fault->message : "");
      EXPECT_EQ(this->dev().status().progress, this->bench.units(kJobPieces));
      done += r.outcome == DeviceState::done;
    }
    EXPECT_TRUE(this->bench.laser_off());
    this->dev().reset();
    this->expect_state(DeviceState::idle);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_EQ(done + aborted + failed, 100);
  EXPECT_EQ(failed, 20);
}

REGISTER_TYPED_TEST_SUITE_P(DeviceLifecycle, StartsIdleWithTheLaserOff, AJobRunsFromIdleToDone,
                            BeginJobOnlyFromIdle, EndJobWithoutAJobIsRefused,
                            ResetWhileRunningIsRefused,
                            ResetFromEveryFinalStateGoesIdleAndIdleStaysIdle,
                            AbortWhileIdleKeepsTheLaserOffUntilReset,
                            AbortWhileRunningEndsTheJobAborted, AbortFromAFinalStateChangesNothing,
                            AFaultFailsTheJobUntilReset, FeedingAnEndedJobIsRefused,
                            AbortFromAnotherThreadStopsWithinOneBlock,
                            StatusDuringAJobFromAnotherThread, HundredJobsInARowReArm);

}  // namespace mark::test
