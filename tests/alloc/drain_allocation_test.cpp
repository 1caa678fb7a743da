// No allocation on the drain thread once a job is running: every global operator new is counted
// per thread, and a device wrapper reads the drain thread's count at its first and last write.
// The job is the cps text (62 characters at 1 mm on SL10, every corner strategy), in virtual and
// in real time, through the real job runner, drain, delay line and simulated scanner.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/job/sim_evaluator.hpp"

namespace {
thread_local std::uint64_t t_allocations = 0;
}  // namespace

void* operator new(std::size_t n) {
  ++t_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, std::align_val_t a) {
  ++t_allocations;
  const std::size_t align = static_cast<std::size_t>(a);
  if (void* p = std::aligned_alloc(align, (n + align - 1) / align * align)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n, std::align_val_t a) { return operator new(n, a); }
// These are the replacement operator new's own partners, so free() matches its malloc(); GCC at
// -O1 sees operator new in the sized delete's caller and warns of a mismatch that is not one.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace mark {
namespace {

// Forwards everything to the simulated scanner and counts the drain thread's allocations from
// the start of its first write to the end of its last.
class CountingDevice : public SampleDevice<ScanSample> {
 public:
  explicit CountingDevice(SimScanner& sim) : sim_(sim) {}
  DeviceDescription describe() const override { return sim_.describe(); }
  void begin_job(const JobHeader& h) override { sim_.begin_job(h); }
  DeviceReport end_job() override { return sim_.end_job(); }
  void abort() noexcept override { sim_.abort(); }
  DeviceStatus status() const override { return sim_.status(); }
  void reset() override { sim_.reset(); }
  void write(std::span<const ScanSample> block) override {
    if (writes_++ == 0) first_ = t_allocations;
    sim_.write(block);
    last_ = t_allocations;
  }
  void halt() noexcept override {
    sim_.halt();
    last_ = t_allocations;
  }
  std::uint64_t allocations() const { return last_ - first_; }
  std::uint64_t writes() const { return writes_; }

 private:
  SimScanner& sim_;
  std::uint64_t writes_ = 0, first_ = 0, last_ = 0;
};

JobSpec cps_job(CornerStrategy corner) {
  JobSpec spec;
  spec.text = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 1;
  spec.layout.align = Align::center;
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, corner, 500);
  return spec;
}

void expect_no_allocation(CornerStrategy corner, bool virtual_time) {
  const JobSpec spec = cps_job(corner);
  SimScanner sim(simulator_options(spec));
  CountingDevice device(sim);
  JobOptions options;
  options.virtual_time = virtual_time;
  const JobResult r = run_job(spec, options, device);
  ASSERT_EQ(r.outcome, JobOutcome::done);
  ASSERT_GT(device.writes(), 100u);  // hundreds of blocks went through the counted window
  EXPECT_EQ(device.allocations(), 0u)
      << to_string(corner) << (virtual_time ? " virtual" : " real") << " time, "
      << r.samples << " samples";
  testing::Test::RecordProperty(std::string("allocations_") + std::string(to_string(corner)) +
                     (virtual_time ? "_virtual" : "_real"),
                 static_cast<int>(device.allocations()));
}

TEST(DrainAllocation, NoneOnTheDrainThreadInVirtualTime) {
  for (CornerStrategy c : {CornerStrategy::blanking, CornerStrategy::delays, CornerStrategy::none})
    expect_no_allocation(c, true);
}

TEST(DrainAllocation, NoneOnTheDrainThreadInRealTime) {
  expect_no_allocation(CornerStrategy::blanking, false);
}

TEST(DrainAllocation, TheCounterSeesAllocationsOnThisThread) {
  // The instrument works: an allocation between two reads is counted.
  const std::uint64_t before = t_allocations;
  auto* p = new int(7);
  EXPECT_EQ(t_allocations, before + 1);
  delete p;
}

}  // namespace
}  // namespace mark
