// Laser safety of a whole job on the simulated scanner: an underrun, a stop or a device fault
// puts the laser out at the sample where it happened and it stays out for the rest of the job;
// the result says where it stopped and how much ink was marked; the same scanner then runs the
// next job; a stop requested from another thread in real time is honoured within one drain
// block of where it fell on the device's clock.
#include <gtest/gtest.h>

#include <atomic>

#include <cmath>
#include <thread>

#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/job/mark_evaluator.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "marker/locus/locus_generator.hpp"

namespace mark {
namespace {

JobSpec serial() {
  JobSpec spec;
  spec.text = "SN 2026-000123";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 3;
  spec.layout.align = Align::center;
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, CornerStrategy::blanking, 800);
  return spec;
}

SimScannerOptions traced(const JobSpec& spec, std::uint64_t fault_at = UINT64_MAX) {
  SimScannerOptions o = simulator_options(spec);
  o.trace = true;
  o.fault_at = fault_at;
  return o;
}

// Lit samples of the job's locus before `n`, over all of them: what ink_marked must say.
double expected_ink(const Plan& plan, std::uint64_t n) {
  LocusGenerator locus(plan.commands, plan.pen.tick_s);
  std::vector<ScanSample> s(LocusGenerator::count_samples(plan.commands, plan.pen.tick_s));
  locus.generate(s.data(), s.size());
  std::uint64_t before = 0, all = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i].laser) ++all, before += i < n;
  return static_cast<double>(before) / static_cast<double>(all);
}

// Every trace row from `from` on: laser commanded off.
void expect_dark_from(const SimScanner& sim, std::uint64_t from) {
  const auto& rows = sim.trace();
  ASSERT_GT(rows.size(), from);
  for (std::size_t i = from; i < rows.size(); ++i)
    ASSERT_FALSE(rows[i].laser) << "row " << i << " of " << rows.size() << " is lit";
}

JobResult run_virtual(const JobSpec& spec, SimScanner& sim, Injection inject = {}) {
  JobOptions o;
  o.virtual_time = true;
  o.inject = inject;
  return run_job_simulated(spec, o, sim);
}

TEST(JobSafety, UnderrunFailsTheJobDarkFromTheMissingSample) {
  const JobSpec spec = serial();
  SimScanner sim(traced(spec));
  const JobResult r = run_virtual(spec, sim, {Injection::Kind::underrun, 4321});
  EXPECT_EQ(r.outcome, JobOutcome::failed);
  ASSERT_TRUE(r.fault);
  EXPECT_EQ(r.fault->category, FaultCategory::underrun);
  EXPECT_EQ(r.fault->at, 4321u);
  EXPECT_EQ(r.stopped_at, 4321u);
  EXPECT_NEAR(r.ink_marked, expected_ink(r.job.plan, 4321), 1e-12);
  EXPECT_GT(r.ink_marked, 0.1);
  EXPECT_LT(r.ink_marked, 0.9);
  expect_dark_from(sim, 4321);
  // The scanner's laser is out, and it stays out: nothing lit after the stop reached the part.
  EXPECT_EQ(sim.laser_power(), 0.0);
  EXPECT_EQ(r.device.outcome, DeviceState::aborted);  // halted by the drain
}

TEST(JobSafety, AbortStopsAtTheSampleAndTheNextJobRunsOnTheSameScanner) {
  const JobSpec spec = serial();
  SimScanner sim(traced(spec));
  const JobResult aborted = run_virtual(spec, sim, {Injection::Kind::abort, 2500});
  EXPECT_EQ(aborted.outcome, JobOutcome::aborted);
  EXPECT_FALSE(aborted.fault);
  EXPECT_EQ(aborted.stopped_at, 2500u);
  EXPECT_EQ(aborted.samples, 2501u);  // the samples before the stop and one safe sample
  expect_dark_from(sim, 2500);
  EXPECT_NEAR(aborted.ink_marked, expected_ink(aborted.job.plan, 2500), 1e-12);

  // A station runs for months: the same scanner marks the next part completely, with the
  // figures of a fresh scanner.
  const JobResult next = run_virtual(spec, sim);
  SimScanner fresh(traced(spec));
  const JobResult reference = run_virtual(spec, fresh);
  EXPECT_EQ(next.outcome, JobOutcome::done);
  EXPECT_EQ(next.samples, reference.samples);
  EXPECT_DOUBLE_EQ(next.quality->coverage, reference.quality->coverage);
  EXPECT_NEAR(next.quality->max_deviation_um, reference.quality->max_deviation_um, 0.5);
}

TEST(JobSafety, DeviceFaultIsReportedWithItsCategoryAndTheLaserStaysOff) {
  const JobSpec spec = serial();
  SimScanner sim(traced(spec, 3333));
  const JobResult r = run_virtual(spec, sim);
  EXPECT_EQ(r.outcome, JobOutcome::failed);
  ASSERT_TRUE(r.fault);
  EXPECT_EQ(r.fault->category, FaultCategory::device);
  EXPECT_EQ(r.stopped_at, 3333u);
  EXPECT_EQ(sim.samples(), 3333u);  // the faulted sample was never followed
  EXPECT_EQ(sim.laser_power(), 0.0);
  EXPECT_EQ(sim.status().state, DeviceState::failed);
  EXPECT_NE(r.fault->message.find("sample 3333"), std::string::npos) << r.fault->message;
}

TEST(JobSafety, StopFromAnotherThreadInRealTimeWithinOneBlock) {
  JobSpec spec = serial();
  spec.pen = pen_for_head(spec.head, CornerStrategy::blanking, 100);  // ≈ 1 s of marking
  SimScanner sim(traced(spec));
  StopFlag stop;
  JobOptions o;
  o.stop = &stop;
  std::int64_t published_ns = 0;
  // The operator waits for 20000 samples, or for the job to end first: a real-time job on an
  // overloaded machine can underrun before then, and the test must fail on that, not wait for
  // ever (it hung a CI rehearsal's ThreadSanitizer run beside a kill test).
  std::atomic<bool> ended{false};
  std::thread operator_([&] {
    while (sim.status().progress < 20000 && !ended.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    if (ended.load()) return;
    stop.request();
    published_ns = StopFlag::now_ns();
  });
  const JobResult r = run_job_simulated(spec, o, sim);
  ended.store(true);
  operator_.join();
  ASSERT_EQ(r.outcome, JobOutcome::aborted) << "the job ended before the stop: "
                                            << (r.fault ? r.fault->message : std::string("done"));
  EXPECT_GE(r.stopped_at, 20000u);
  // The drain checks after every wait: at most one block (100 samples = 1 ms) after the request
  // fell on the device's clock, the laser is out. The request's time is taken before its flag
  // is published, and the operator's thread can be preempted in between (CI's ThreadSanitizer
  // run on a loaded machine saw 101 samples); the drain cannot see a request before it is
  // published, so the samples of that gap are the scheduler's, not the drain's.
  const double publish_gap_samples =
      static_cast<double>(published_ns - stop.requested_at_ns()) * 1e-9 / r.job.plan.pen.tick_s;
  EXPECT_LE(static_cast<double>(r.stop_latency_samples), 100.0 + std::ceil(publish_gap_samples))
      << "publishing the request took " << publish_gap_samples << " samples";
  EXPECT_GE(r.stop_latency_us, 0.0);
  expect_dark_from(sim, r.stopped_at);
  EXPECT_LT(r.ink_marked, 1.0);
}

// A station's ABORT raises the stop flag and then aborts the device. Landing after the runner
// re-armed the device but before begin_job, abort() finds it idle and leaves it aborted, and
// begin_job refuses: the job must end aborted with nothing marked, not failed (CI saw the station
// go to `error` over it). The evaluator's begin() runs in exactly that window.
TEST(JobSafety, AStopJustBeforeBeginJobEndsTheJobAbortedWithNothingMarked) {
  const JobSpec spec = serial();
  SimScanner sim(traced(spec));
  StopFlag stop;
  struct AbortAtBegin : MarkEvaluator {
    SimScanner& device;
    StopFlag& stop;
    bool evaluated = false;
    AbortAtBegin(SimScanner& d, StopFlag& s) : device(d), stop(s) {}
    void begin(const JobSpec&, const CompiledJob&) override {
      stop.request();
      device.abort();
    }
    void evaluate(const JobSpec&, JobResult&) override { evaluated = true; }
  } evaluator(sim, stop);
  JobOptions o;
  o.virtual_time = true;
  o.stop = &stop;
  o.evaluator = &evaluator;
  const JobResult r = run_job(spec, o, sim);
  EXPECT_EQ(r.outcome, JobOutcome::aborted);
  EXPECT_FALSE(r.fault);
  EXPECT_EQ(r.samples, 0u);
  EXPECT_EQ(r.ink_marked, 0.0);
  EXPECT_TRUE(evaluator.evaluated);
  EXPECT_TRUE(sim.trace().empty());  // not one sample reached the scanner
  EXPECT_EQ(sim.status().state, DeviceState::aborted);

  // Without the stop flag the same refusal is a misuse of the lifecycle and is not hidden.
  StopFlag none;
  struct AbortOnly : MarkEvaluator {
    SimScanner& device;
    explicit AbortOnly(SimScanner& d) : device(d) {}
    void begin(const JobSpec&, const CompiledJob&) override { device.abort(); }
    void evaluate(const JobSpec&, JobResult&) override {}
  } abort_only(sim);
  o.stop = &none;
  o.evaluator = &abort_only;
  EXPECT_THROW(run_job(spec, o, sim), DeviceStateError);

  // The next job re-arms the scanner and marks the whole part.
  o.evaluator = nullptr;
  EXPECT_EQ(run_job(spec, o, sim).outcome, JobOutcome::done);
}

TEST(JobSafety, DoneJobReportsTheWholeInk) {
  const JobSpec spec = serial();
  SimScanner sim(traced(spec));
  const JobResult r = run_virtual(spec, sim);
  EXPECT_EQ(r.outcome, JobOutcome::done);
  EXPECT_EQ(r.ink_marked, 1.0);
  EXPECT_EQ(sim.trace().size(), r.samples);
  EXPECT_FALSE(sim.trace().back().laser);  // the closing safe sample
  EXPECT_EQ(r.device.outcome, DeviceState::done);
}

}  // namespace
}  // namespace mark
