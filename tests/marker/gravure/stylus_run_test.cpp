// A stylus job through the line memory and the drain ends the drain's way: completed with a
// closing safe sample, or an underrun (a fault, stylus lifted), or a fault of the head (a drive
// beyond its amplifier, refused) — and the result says which and where.
#include "marker/gravure/stylus_run.hpp"

#include <gtest/gtest.h>

#include "driver/sim/sim_stylus_head.hpp"
#include "marker/gravure/stylus_head_response.hpp"

namespace mark {
namespace {

// A constant drive for a given number of samples.
class Constant : public DriveSource {
 public:
  Constant(std::uint64_t n, double drive) : n_(n), drive_(drive) {}
  std::uint64_t total_samples() const override { return n_; }
  std::size_t next(std::span<double> out) override {
    const std::size_t k = static_cast<std::size_t>(std::min<std::uint64_t>(out.size(), n_ - at_));
    std::fill_n(out.begin(), k, drive_);
    at_ += k;
    return k;
  }

 private:
  std::uint64_t n_, at_ = 0;
  double drive_;
};

TEST(StylusRun, CompletesOnTheSafeSample) {
  SimStylusHead head;
  Constant deep(10000, 25);
  const StylusRunResult r = run_stylus_job(deep, nullptr, head, {});
  EXPECT_EQ(r.drain.end, DrainEnd::completed);
  EXPECT_EQ(r.report.outcome, DeviceState::done);
  EXPECT_EQ(r.samples, 10000u);
  EXPECT_EQ(r.report.samples_out, 10001u);
  EXPECT_FALSE(r.fault.has_value());
  EXPECT_NEAR(head.cut_profile_um()[9999], 25, 1e-3);
  EXPECT_EQ(head.cut_profile_um()[10000], 0.0f);
}

TEST(StylusRun, AnUnderrunIsAFaultThatLiftsTheStylus) {
  SimStylusHead head;
  Constant deep(10000, 25);
  StylusRunOptions o;
  o.starve_at = 3000;
  const StylusRunResult r = run_stylus_job(deep, nullptr, head, o);
  EXPECT_EQ(r.drain.end, DrainEnd::underrun);
  ASSERT_TRUE(r.fault.has_value());
  EXPECT_EQ(r.fault->category, FaultCategory::underrun);
  EXPECT_EQ(r.stopped_at, 3000u);
  EXPECT_EQ(r.report.outcome, DeviceState::aborted);
  const auto& cut = head.cut_profile_um();
  EXPECT_GT(cut[2999], 20);
  for (std::size_t k = 3000; k < cut.size(); ++k) ASSERT_EQ(cut[k], 0.0f) << k;
}

TEST(StylusRun, ADriveBeyondTheAmplifierIsRefusedAndReported) {
  SimStylusHeadOptions ho;
  ho.max_drive_um = 20;
  SimStylusHead head(ho);
  Constant deep(10000, 25);
  const StylusRunResult r = run_stylus_job(deep, nullptr, head, {});
  EXPECT_EQ(r.drain.end, DrainEnd::device_fault);
  ASSERT_TRUE(r.fault.has_value());
  EXPECT_EQ(r.fault->category, FaultCategory::out_of_field);
  EXPECT_EQ(r.fault->at, 0u);
  EXPECT_EQ(r.report.outcome, DeviceState::failed);
  EXPECT_TRUE(head.lifted());
  EXPECT_EQ(head.samples(), 0u);
}

TEST(StylusRun, TheStreamFiltersEverySampleBeforeTheMemory) {
  // A constant drive through a notch: the filters start settled, so the output is the input
  // divided by the bank's gain, from the first sample.
  Constant c(5000, -10);
  const FilterBank bank{{notch_section(1800, 0.06, 18)}, 0.5};
  StylusSampleStream stream(c, &bank);
  std::vector<StylusSample> out(5000);
  ASSERT_EQ(stream.next(out), 5000u);
  for (const StylusSample& s : out) {
    ASSERT_NEAR(s.drive_um, -5, 1e-5);
    ASSERT_FALSE(s.lifted);
  }
}

}  // namespace
}  // namespace mark
