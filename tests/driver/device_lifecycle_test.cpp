// The lifecycle suite (device_lifecycle_suite.hpp) on the simulated scanner, the simulated
// stylus head, the LMC device on the in-process emulated board and the LMC device writing a
// capture file. (lmc_usb_tests runs it through libusb and umockdev.)
#include <unistd.h>

#include <filesystem>

#include "driver/lmc/capture_link.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "driver/sim/sim_stylus_head.hpp"
#include "tests/driver/device_lifecycle_suite.hpp"
#include "tests/driver/lmc/lmc_lifecycle_bench.hpp"

namespace mark::test {
namespace {

// 1 ms blocks at 10 µs around a 20 mm square at 1000 mm/s, laser on.
struct SimScannerBench {
  static constexpr std::size_t kBlock = 100;
  static constexpr bool kSeesLaserWhileFed = false;  // the beam is the drain thread's
  static std::string name() { return "SimScanner"; }
  SimScanner sim;
  Device& device() { return sim; }
  JobHeader header() {
    JobHeader h;
    h.name = "lifecycle";
    h.field_mm = 110;
    h.pens = {DevicePen{}};
    h.expected_samples = kMaxPieces * kBlock;
    return h;
  }
  static std::vector<ScanSample> block(std::size_t k) {
    std::vector<ScanSample> b(kBlock);
    for (std::size_t i = 0; i < kBlock; ++i) {
      const double s = std::fmod(0.01 * double(k * kBlock + i), 80.0);  // along the perimeter
      const int side = static_cast<int>(s / 20);
      const double t = s - 20 * side - 10;
      const double x = side == 0 ? t : side == 1 ? 10 : side == 2 ? -t : -10;
      const double y = side == 0 ? -10 : side == 1 ? t : side == 2 ? 10 : -t;
      b[i] = {static_cast<float>(x), static_cast<float>(y), true, 255};
    }
    return b;
  }
  void feed(std::size_t k) { sim.write(block(k)); }
  void feed_outside(std::size_t k) {
    std::vector<ScanSample> b = block(k);
    b[kBlock / 2].x_mm = 60;
    sim.write(b);
  }
  std::uint64_t units(std::size_t pieces) const { return pieces * kBlock; }
  std::uint64_t stop_bound() const { return kBlock; }
  bool laser_off() const { return !sim.laser_commanded() && sim.laser_power() == 0; }
  double half_field_mm() const { return 55; }
};

// 1 ms blocks at the 200 kHz stylus clock, 20 µm deep (cutting).
struct SimStylusHeadBench {
  static constexpr std::size_t kBlock = 200;
  static constexpr bool kSeesLaserWhileFed = true;  // lifted() is atomic
  static std::string name() { return "SimStylusHead"; }
  static SimStylusHeadOptions options() {
    SimStylusHeadOptions o;
    o.sense_noise_um = 0;
    return o;
  }
  SimStylusHead head{options()};
  Device& device() { return head; }
  JobHeader header() {
    JobHeader h;
    h.name = "lifecycle";
    h.expected_samples = kMaxPieces * kBlock;
    return h;
  }
  void feed(std::size_t) { head.write(std::vector<StylusSample>(kBlock, StylusSample{20, false})); }
  void feed_outside(std::size_t) {
    std::vector<StylusSample> b(kBlock, StylusSample{20, false});
    b[kBlock / 2].drive_um = 1500;  // beyond the amplifier's ±1000 µm
    head.write(b);
  }
  std::uint64_t units(std::size_t pieces) const { return pieces * kBlock; }
  std::uint64_t stop_bound() const { return kBlock; }
  bool laser_off() const { return head.lifted(); }  // the diamond clear of the copper
  double half_field_mm() const { return 0; }        // a stylus moves in depth only
};

// The emulated board on its own clock (4 × real time) behind the loopback link.
struct LmcEmulatedBench : lmc::test::LmcBenchBase {
  static std::string name() { return "LmcEmulated"; }
  lmc::test::LoopbackBench rig{{}, {}, lmc::test::quick_options(), 4.0};
  lmc::LmcDevice& lmc() override { return *rig.device; }
  bool laser_off() const { return lmc::test::board_laser_off(rig.board); }
};

// A capture file: no board, the bytes for endpoint 0x02; the laser is the last port write.
class PortWatch : public lmc::CaptureLink {
 public:
  PortWatch(std::string path, std::atomic<std::uint16_t>& port) : CaptureLink(std::move(path)), port_(port) {}
  void write(std::span<const std::uint8_t> bytes) override {
    if (bytes.size() == lmc::kCommandBytes) {
      const lmc::Word w = lmc::load(bytes.data());
      if (w.opcode() == static_cast<std::uint16_t>(lmc::Op::WritePort)) port_ = w.p(1);
    }
    CaptureLink::write(bytes);
  }

 private:
  std::atomic<std::uint16_t>& port_;
};

// Removed after the device (declared before it): the device's link writes the file last.
struct TempFile {
  std::string path;
  ~TempFile() { std::filesystem::remove(path); }
};

struct LmcCaptureBench : lmc::test::LmcBenchBase {
  static std::string name() { return "LmcCapture"; }
  TempFile file{(std::filesystem::temp_directory_path() /
                 ("lifecycle_" + std::to_string(::getpid()) + "_" +
                  std::to_string(reinterpret_cast<std::uintptr_t>(this)) + ".lmc"))
                    .string()};
  std::atomic<std::uint16_t> port{0xFFFF};
  lmc::LmcDevice dev{std::make_unique<PortWatch>(file.path, port), lmc::test::quick_options()};
  lmc::LmcDevice& lmc() override { return dev; }
  bool laser_off() const { return (port.load() & 0x0001) == 0; }
};

using Benches = ::testing::Types<SimScannerBench, SimStylusHeadBench, LmcEmulatedBench, LmcCaptureBench>;
INSTANTIATE_TYPED_TEST_SUITE_P(Every, DeviceLifecycle, Benches, BenchName);

}  // namespace
}  // namespace mark::test
