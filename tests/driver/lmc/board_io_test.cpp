// Board I/O on the LMC driver (issue 22): the input port read with ReadPort and the station's
// output bits OR'ed into the port words. Checked against meerk40t's bytes (galvoplotter
// controller.py: read_port() is `_command(ReadPort)` = struct.pack("<6H", 0x0025, 0, 0, 0, 0, 0),
// and the pins are its reply's w1, `read_port[1]`; write_port() is `_command(WritePort,
// port_bits)`) and against what the emulated board was given and took.
#include <gtest/gtest.h>

#include <mutex>

#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc {
namespace {

// Every transfer's bytes as they leave the host, then on to the emulated board.
class RecordingLink : public LmcLink {
 public:
  explicit RecordingLink(EmulatedBoard& board) : inner_(board) {}
  void write(std::span<const std::uint8_t> bytes) override {
    {
      std::lock_guard lock(m_);
      out_.emplace_back(bytes.begin(), bytes.end());
    }
    inner_.write(bytes);
  }
  std::array<std::uint8_t, kReplyBytes> read() override {
    auto r = inner_.read();
    std::lock_guard lock(m_);
    in_.push_back(r);
    return r;
  }
  std::string name() const override { return "recording"; }
  std::vector<std::vector<std::uint8_t>> out() const {
    std::lock_guard lock(m_);
    return out_;
  }
  std::vector<std::array<std::uint8_t, kReplyBytes>> in() const {
    std::lock_guard lock(m_);
    return in_;
  }

 private:
  LoopbackLink inner_;
  mutable std::mutex m_;
  std::vector<std::vector<std::uint8_t>> out_;
  std::vector<std::array<std::uint8_t, kReplyBytes>> in_;
};

TEST(LmcBoardIo, ReadPortBytesAreMeerk40tsAndTheReplyIsTheBoardsInputWord) {
  EmulatedBoard board;
  board.start_clock();
  auto link = std::make_unique<RecordingLink>(board);
  RecordingLink* rec = link.get();
  LmcDevice dev(std::move(link), test::quick_options());
  for (const std::uint16_t pins : {std::uint16_t{0x0000}, std::uint16_t{0x8000}, std::uint16_t{0x0009},
                                   std::uint16_t{0xFFFF}}) {
    board.set_inputs(pins);
    const std::size_t before = rec->out().size();
    EXPECT_EQ(dev.read_inputs(), pins);
    const auto out = rec->out();
    ASSERT_EQ(out.size(), before + 1);
    // struct.pack("<6H", 0x0025, 0, 0, 0, 0, 0)
    const std::vector<std::uint8_t> meerk40t{0x25, 0x00, 0x00, 0x00, 0x00, 0x00,
                                             0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
    EXPECT_EQ(out.back(), meerk40t);
    // The reply's w1 (bytes 2–3, little-endian) carries the pins, as read_port()[1] reads them.
    const auto reply = rec->in().back();
    EXPECT_EQ(reply[2] | (reply[3] << 8), pins);
  }
  EXPECT_EQ(board.state().read_ports, 4u);
  board.stop_clock();
}

TEST(LmcBoardIo, SignalBitsJoinThePortWordAndNeverTheLaserOrRedPointerBits) {
  test::LoopbackBench bench;
  LmcDevice& dev = *bench.device;
  EXPECT_EQ(dev.reserved_port_bits(), 0x0101);  // laser bit 0, red pointer bit 8
  dev.set_signal_bits(0x0101 | 0x0C00);
  EXPECT_EQ(dev.signal_bits(), 0x0C00) << "the laser and red-pointer bits are masked off";
  ASSERT_TRUE(dev.write_outputs());
  EXPECT_EQ(bench.board.state().port, 0x0C00);
  // WritePort(0x0C00) on the wire: struct.pack("<6H", 0x0021, 0x0C00, 0, 0, 0, 0).
  EXPECT_EQ(test::singles(bench.board.wire()).back(), word(Op::WritePort, 0x0C00));
  dev.set_red_pointer(true);
  EXPECT_EQ(bench.board.state().port, 0x0D00);
  dev.set_signal_bits(0x0400);
  ASSERT_TRUE(dev.write_outputs());
  EXPECT_EQ(bench.board.state().port, 0x0500) << "the red pointer stays as it was set";
  dev.set_red_pointer(false);
  EXPECT_EQ(bench.board.state().port, 0x0400);
}

// A job's port words with and without signal bits differ only in those bits.
std::vector<PortWrite> job_port_words(std::uint16_t signals) {
  test::LoopbackBench bench;
  bench.device->set_signal_bits(signals);
  const std::size_t before = bench.board.port_writes().size();
  bench.device->begin_job(test::header_with(test::fast_pen()));
  bench.device->submit(test::golden_rectangle_commands());
  EXPECT_EQ(bench.device->end_job().outcome, DeviceState::done);
  const auto all = bench.board.port_writes();
  return {all.begin() + static_cast<std::ptrdiff_t>(before), all.end()};
}

TEST(LmcBoardIo, ALaserJobsPortWordsDifferOnlyInTheSignalBits) {
  const auto plain = job_port_words(0);
  const auto signalled = job_port_words(0x3000);
  ASSERT_EQ(plain.size(), signalled.size());
  ASSERT_GE(plain.size(), 3u);  // WritePort(laser), the list's WritePort(laser), WritePort(off)
  bool laser_seen = false;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(plain[i].list, signalled[i].list) << i;
    EXPECT_EQ(plain[i].bits | 0x3000, signalled[i].bits) << i;
    laser_seen = laser_seen || (plain[i].bits & 1);
  }
  EXPECT_TRUE(laser_seen);
  EXPECT_EQ(plain.back().bits & 1, 0) << "the job ends with the laser port off";
}

TEST(LmcBoardIo, TheStopSequencesPortOffKeepsTheSignalsAndClearsTheLaser) {
  test::LoopbackBench bench;
  bench.device->set_signal_bits(0x0200);
  const std::size_t before = bench.board.port_writes().size();  // the init's WritePort(0)
  bench.device->begin_job(test::header_with(test::fast_pen()));
  bench.device->submit(test::zigzag(3000));
  bench.device->abort();
  const auto words = bench.board.port_writes();
  ASSERT_GT(words.size(), before + 1);
  EXPECT_EQ(words.back().bits, 0x0200) << "laser off, signal kept";
  for (std::size_t i = before; i < words.size(); ++i) EXPECT_EQ(words[i].bits & 0x0200, 0x0200) << i;
}

}  // namespace
}  // namespace mark::lmc
