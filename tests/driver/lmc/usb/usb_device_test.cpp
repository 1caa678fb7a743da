// The driver's real libusb path against the emulated board behind usbfs ioctls (umockdev):
// discovery by VID/PID and serial, the init sequence, the golden job, flow control, and the
// faults a USB cable brings — stall (cleared through the real CLEAR_HALT), a board that stops
// answering (libusb's timeout and DISCARDURB), unplugging mid-job. Transfers cost about 1.4 ms
// per round trip here, so the jobs are a few packets long.
#include <gtest/gtest.h>

#include <cstdio>

#include "driver/lmc/usb_discovery.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"
#include "tests/driver/lmc/usb/umockdev_board.hpp"

namespace mark::lmc {
namespace {

using test::figure;

// A testbed with one emulated board on its clock, and an LmcDevice opened through libusb.
struct UsbBench {
  explicit UsbBench(BoardOptions bo = {}, BoardFaults faults = {},
                    LmcOptions options = test::quick_options())
      : board(bo, faults), usb(testbed.get(), board) {
    board.start_clock();
    device = std::make_unique<LmcDevice>(open_usb_board(""), options);
  }
  ~UsbBench() {
    device.reset();
    board.stop_clock();
  }
  test::Testbed testbed;
  EmulatedBoard board;
  test::UmockdevBoard usb;
  std::unique_ptr<LmcDevice> device;
};

BoardState settled(const EmulatedBoard& board) {
  for (int i = 0; i < 500 && board.state().executing; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return board.state();
}

TEST(LmcUsb, DiscoveryListsBoardsWithTheirSerials) {
  test::Testbed tb;
  BoardOptions a, b;
  a.serial = 0x00001234;
  b.serial = 0xABCD0042;
  EmulatedBoard board_a(a), board_b(b);
  test::UmockdevBoard usb_a(tb.get(), board_a, 0), usb_b(tb.get(), board_b, 1);
  const auto boards = list_usb_boards();
  ASSERT_EQ(boards.size(), 2u);
  EXPECT_EQ(boards[0].bus, 1);
  EXPECT_EQ(boards[0].address, 2);
  EXPECT_EQ(boards[0].serial, "00001234");
  EXPECT_TRUE(boards[0].usable);
  EXPECT_EQ(boards[1].address, 3);
  EXPECT_EQ(boards[1].serial, "ABCD0042");
  EXPECT_EQ(boards[0].vendor_id, 0x9588);
  EXPECT_EQ(boards[0].product_id, 0x9899);

  try {
    open_usb_board("");
    FAIL() << "two boards, no serial: must refuse";
  } catch (const LinkError& e) {
    EXPECT_NE(std::string(e.what()).find("several boards found"), std::string::npos) << e.what();
  }
  const auto link = open_usb_board("abcd0042");
  EXPECT_EQ(link->address(), 3);
  try {
    open_usb_board("77777777");
    FAIL();
  } catch (const LinkError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("no LMC board with serial 77777777 found (found:"), std::string::npos) << m;
    EXPECT_NE(m.find("00001234"), std::string::npos) << m;
    EXPECT_NE(m.find("ABCD0042"), std::string::npos) << m;
  }
}

TEST(LmcUsb, NoBoardIsAClearError) {
  test::Testbed tb;
  EXPECT_TRUE(list_usb_boards().empty());
  try {
    open_usb_board("");
    FAIL();
  } catch (const LinkError& e) {
    EXPECT_EQ(e.failure(), LinkFailure::no_device);
    EXPECT_NE(std::string(e.what()).find("no LMC board (USB 9588:9899) found"), std::string::npos);
  }
}

TEST(LmcUsb, InitSequenceAndGoldenJobCrossRealUsbfs) {
  UsbBench bench(test::golden_board(), {}, test::golden_options());
  // Discovery asked for the serial to pick the board, then the init sequence went out.
  const auto init = test::singles(bench.board.wire());
  ASSERT_GE(init.size(), 21u);
  EXPECT_EQ(init[0], word(Op::GetSerialNo));
  EXPECT_EQ(std::vector<Word>(init.begin() + 1, init.begin() + 21), test::expected_init());
  EXPECT_EQ(bench.device->identity().serial, "4C4D4301");

  LmcDevice& dev = *bench.device;
  DevicePen pen = test::golden_pen();
  pen.mark_speed_mm_s = 1500;  // the golden rectangle itself takes 3 s at 15 mm/s
  dev.begin_job(test::header_with(pen));
  dev.submit(test::golden_rectangle_commands());
  const DeviceReport r = dev.end_job();
  ASSERT_EQ(r.outcome, DeviceState::done) << (r.fault ? r.fault->message : "");
  const auto packets = bench.board.packets();
  ASSERT_EQ(packets.size(), 1u);
  auto golden = test::golden_rectangle_words();
  golden[6] = word(Op::MarkSpeed, encode_speed(1500, FieldUnits(110)));
  for (std::size_t i = 0; i < golden.size(); ++i) EXPECT_EQ(packets[0][i], golden[i]) << i;
  EXPECT_EQ(bench.board.state().executor.moves, 5u);
  EXPECT_TRUE(bench.board.violations().empty());
  EXPECT_GT(bench.usb.ioctls(), 50u);  // it really went through the handler
}

TEST(LmcUsb, FlowControlOverUsb) {
  BoardOptions bo;
  bo.list_capacity = 3;
  UsbBench bench(bo);
  const auto cmds = test::zigzag(1500);
  bench.device->begin_job(test::header_with(test::fast_pen()));
  bench.device->submit(cmds);
  const DeviceReport r = bench.device->end_job();
  ASSERT_EQ(r.outcome, DeviceState::done) << (r.fault ? r.fault->message : "");
  EXPECT_EQ(figure(r, "packets"), 6);
  EXPECT_GT(figure(r, "ready_waits"), 0);
  for (const WireRecord& w : bench.board.wire())
    if (w.packet) {
      EXPECT_TRUE(w.status & status::ready) << "packet " << w.packet_number;
    }
  const BoardState s = bench.board.state();
  EXPECT_EQ(s.packets_received, 6u);
  EXPECT_EQ(s.packets_lost, 0u);
  EXPECT_EQ(s.executor.moves, cmds.size());
  EXPECT_EQ(s.executor.underrun_events, 0u);
  EXPECT_TRUE(bench.board.violations().empty());
}

TEST(LmcUsb, StallIsClearedToSwitchTheLaserOff) {
  BoardFaults f;
  f.stall_at_packet = 4;
  UsbBench bench({}, f);
  bench.device->begin_job(test::header_with(test::fast_pen()));
  try {
    bench.device->submit(test::zigzag(1500));
    FAIL() << "no fault";
  } catch (const DeviceFaultError& e) {
    EXPECT_EQ(e.fault().category, FaultCategory::transport);
    EXPECT_EQ(e.fault().at, 3 * 256u - 11u);
    const std::string m = e.what();
    EXPECT_NE(m.find("LIBUSB_ERROR_PIPE"), std::string::npos) << m;
    EXPECT_NE(m.find("; stopped, laser port off confirmed"), std::string::npos) << m;
  }
  const BoardState s = settled(bench.board);
  EXPECT_EQ(s.port & 1, 0);
  EXPECT_FALSE(s.laser_emitting);
  EXPECT_FALSE(s.executing);
  EXPECT_FALSE(s.mo_open);
}

TEST(LmcUsb, ABoardThatStopsAnsweringTimesOut) {
  BoardFaults f;
  f.hang_at_packet = 2;
  f.hang_s = 0.15;  // back before the stop sequence's second step
  UsbBench bench({}, f);
  bench.device->begin_job(test::header_with(test::fast_pen()));
  EXPECT_THROW(bench.device->submit(test::zigzag(1000)), DeviceFaultError);
  const DeviceReport r = bench.device->end_job();
  ASSERT_TRUE(r.fault);
  EXPECT_EQ(r.fault->category, FaultCategory::timeout);
  EXPECT_NE(r.fault->message.find("LIBUSB_ERROR_TIMEOUT"), std::string::npos) << r.fault->message;
  EXPECT_EQ(r.fault->at, 0u);
  // libusb waited its 100 ms; the report says how long the link had been silent.
  EXPECT_GE(figure(r, "fault_latency_s"), 0.09);
  EXPECT_LT(figure(r, "fault_latency_s"), 0.2 + 0.1);
}

TEST(LmcUsb, UnplugMidJobIsReportedWithin200ms) {
  BoardFaults f;
  f.unplug_after_execute_s = 0.02;
  UsbBench bench({}, f);
  bench.device->begin_job(test::header_with(test::fast_pen()));
  try {
    bench.device->submit(test::zigzag(1500));
  } catch (const DeviceFaultError&) {
  }
  const DeviceReport r = bench.device->end_job();
  ASSERT_EQ(r.outcome, DeviceState::failed);
  ASSERT_TRUE(r.fault);
  EXPECT_EQ(r.fault->category, FaultCategory::transport);
  EXPECT_NE(r.fault->message.find("LIBUSB_ERROR_NO_DEVICE"), std::string::npos) << r.fault->message;
  EXPECT_NE(r.fault->message.find("could not be reached"), std::string::npos) << r.fault->message;
  EXPECT_GT(r.fault->at, 0u);  // the list had started
  EXPECT_LT(figure(r, "fault_latency_s"), 0.2);
  std::printf("unplug reported %.1f ms after the last good transfer\n", 1e3 * figure(r, "fault_latency_s"));
  EXPECT_TRUE(bench.board.unplugged());
  EXPECT_THROW(bench.device->reset(), DeviceFaultError);
}

}  // namespace
}  // namespace mark::lmc

// `marker devices` and `marker frame --device lmc` on the command line, against the same
// emulated board (the CLI runs in-process, under the same umockdev preload).
#include <nlohmann/json.hpp>

#include "tests/marker/cli_runner.hpp"

namespace mark::lmc {
namespace {

TEST(LmcUsbCli, DevicesListsTheBoards) {
  test::Testbed tb;
  BoardOptions a;
  a.serial = 0x00C0FFEE;
  EmulatedBoard board(a);
  test::UmockdevBoard usb(tb.get(), board);
  auto r = mark::test::run_cli({"devices", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["boards"].size(), 1u);
  const auto& b = j["boards"][0];
  EXPECT_EQ(b["bus"], 1);
  EXPECT_EQ(b["address"], 2);
  EXPECT_EQ(b["usb_id"], "9588:9899");
  EXPECT_EQ(b["serial"], "00C0FFEE");
  EXPECT_EQ(b["device"], "lmc:00C0FFEE");
  EXPECT_EQ(b["usable"], true);
  EXPECT_EQ(b["sources"], nlohmann::json::array({"fiber", "mopa", "co2", "uv"}));
  r = mark::test::run_cli({"devices"});
  EXPECT_NE(r.out.find("bus 001 address 002"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("serial 00C0FFEE  (--device lmc:00C0FFEE)"), std::string::npos) << r.out;
}

TEST(LmcUsbCli, MarkOnTheBoard) {
  test::Testbed tb;
  EmulatedBoard board;
  test::UmockdevBoard usb(tb.get(), board);
  board.start_clock();
  const auto r = mark::test::run_cli({"mark", "SN 42", "--height", "2", "--device", "lmc",
                                      "--power", "60", "--frequency", "25", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "done");
  EXPECT_EQ(j["device"], "lmc 4C4D4301");
  const auto& f = j["device_figures"];
  EXPECT_EQ(f["packets"], 1);
  EXPECT_GT(f["commands"].get<double>(), 20);
  // The pen's laser settings went to the board: 60 % of 4095, 20000 / 25 kHz.
  bool power = false, period = false;
  const auto packets = board.packets();
  ASSERT_EQ(packets.size(), 1u);
  for (const Word& w : packets[0]) {
    power |= w == word(Op::MarkCurrent, 2457);
    period |= w == word(Op::QSwitchPeriod, 800);
  }
  EXPECT_TRUE(power);
  EXPECT_TRUE(period);
  const BoardState s = board.state();
  EXPECT_TRUE(s.finished);
  EXPECT_GT(s.executor.lit_ticks, 0u);
  EXPECT_EQ(s.port, 0);
  EXPECT_TRUE(board.violations().empty());
  board.stop_clock();
}

TEST(LmcUsbCli, FrameTracesTheBoxWithTheRedPointer) {
  test::Testbed tb;
  EmulatedBoard board;
  test::UmockdevBoard usb(tb.get(), board);
  board.start_clock(4);
  const auto r = mark::test::run_cli({"frame", "SN 42", "--height", "2", "--device", "lmc:4C4D4301",
                                      "--laps", "2", "--no-orientation-mark", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["laps"], 2);
  const BoardState s = board.state();
  EXPECT_EQ(s.executor.lit_ticks, 0u);
  EXPECT_EQ(s.port, 0);
  const auto path = board.red_path();
  ASSERT_EQ(path.size(), 1 + 5 + 4u);
  const double w = j["width_mm"], h = j["height_mm"];
  EXPECT_NEAR(path[2].x - path[1].x, w, 0.004);
  EXPECT_NEAR(path[3].y - path[2].y, h, 0.004);
  board.stop_clock();
}

}  // namespace
}  // namespace mark::lmc
