// The lifecycle suite (tests/driver/device_lifecycle_suite.hpp) on the LMC device through the
// real libusb path: usbfs ioctls served by umockdev from the emulated board (4 × real time).
#include "driver/lmc/usb_discovery.hpp"
#include "tests/driver/device_lifecycle_suite.hpp"
#include "tests/driver/lmc/lmc_lifecycle_bench.hpp"
#include "tests/driver/lmc/usb/umockdev_board.hpp"

namespace mark::lmc::test {
namespace {

struct LmcUsbBench : LmcBenchBase {
  static std::string name() { return "LmcUsb"; }
  LmcUsbBench() : usb(testbed.get(), board) {
    board.start_clock(4.0);
    dev = std::make_unique<LmcDevice>(open_usb_board(""), quick_options());
  }
  ~LmcUsbBench() override {
    dev.reset();
    board.stop_clock();
  }
  LmcDevice& lmc() override { return *dev; }
  bool laser_off() const { return board_laser_off(board); }

  Testbed testbed;
  EmulatedBoard board;
  UmockdevBoard usb;
  std::unique_ptr<LmcDevice> dev;
};

}  // namespace
}  // namespace mark::lmc::test

namespace mark::test {
using UsbBenches = ::testing::Types<lmc::test::LmcUsbBench>;
INSTANTIATE_TYPED_TEST_SUITE_P(Usb, DeviceLifecycle, UsbBenches, BenchName);
}  // namespace mark::test
