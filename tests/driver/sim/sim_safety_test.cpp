// Laser safety of the simulated scanner: a block with any sample outside the field (or not a
// number) is refused whole, the laser goes off and stays off, the error names the coordinate;
// through a drain the fault halts the device and reaches the joiner.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "driver/device_error.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "ringbuffer/drain.hpp"
#include "tests/driver/command_streams.hpp"

namespace mark {
namespace {

std::string refusal(SimScanner& sim, std::vector<ScanSample> block) {
  try {
    sim.write(block);
  } catch (const DeviceError& e) {
    return e.what();
  }
  return "";
}

TEST(SimSafety, SampleOutsideTheFieldIsRefusedAndTheLaserGoesOff) {
  SimScanner sim;
  test::Stream lit;
  lit.move({5, 0}, 1000, true);
  sim.write(lit.samples());
  ASSERT_TRUE(sim.laser_commanded());
  ASSERT_GT(sim.laser_power(), 0.0);
  const Vec2 before = sim.beam();
  const auto samples_before = sim.samples();

  // The valid first sample of the block is not followed either: the block is refused whole.
  const std::string msg = refusal(sim, {{5.1f, 0, true, 255}, {60.5f, 0, true, 255}});
  EXPECT_NE(msg.find("x = 60.5000 mm"), std::string::npos) << msg;
  EXPECT_NE(msg.find("±55.000 mm"), std::string::npos) << msg;
  EXPECT_NE(msg.find("sample " + std::to_string(samples_before + 1)), std::string::npos) << msg;
  EXPECT_TRUE(sim.halted());
  EXPECT_FALSE(sim.laser_commanded());
  EXPECT_EQ(sim.laser_power(), 0.0);
  EXPECT_EQ(sim.samples(), samples_before);
  EXPECT_EQ(sim.beam().x, before.x);

  // Halted stays halted: nothing more is followed, the laser stays off.
  EXPECT_NE(refusal(sim, {{1, 1, true, 255}}).find("halted"), std::string::npos);
  EXPECT_EQ(sim.laser_power(), 0.0);
  EXPECT_EQ(sim.samples(), samples_before);
}

TEST(SimSafety, EdgeOfTheFieldIsAllowedYAndNanAreChecked) {
  SimScanner edge;
  EXPECT_NO_THROW(edge.write(std::vector<ScanSample>{{55.0f, -55.0f, false, 255}}));
  SimScanner y;
  EXPECT_NE(refusal(y, {{0, -55.01f, false, 255}}).find("y = -55.0100 mm"), std::string::npos);
  SimScanner nan;
  EXPECT_NE(refusal(nan, {{std::numeric_limits<float>::quiet_NaN(), 0, false, 255}}).find("x = nan"),
            std::string::npos);
}

TEST(SimSafety, FieldFaultThroughTheDrainHaltsAndReachesTheJoiner) {
  LineMemory<ScanSample> memory(1024);
  SimScanner sim;
  Drain<ScanSample> drain(memory, sim, {.block_samples = 100, .virtual_time = true});
  drain.start();
  test::Stream s;
  s.move({10, 0}, 1000, true).move({70, 0}, 1000, true);  // leaves the field at x = 55
  const bool all_stored = memory.push(std::span<const ScanSample>(s.samples()));
  memory.close();
  EXPECT_THROW(drain.join(), DeviceError);
  EXPECT_TRUE(sim.halted());
  EXPECT_EQ(sim.laser_power(), 0.0);
  EXPECT_LE(sim.beam().x, 55.0);
  EXPECT_TRUE(memory.aborted());
  (void)all_stored;  // the producer may or may not have finished before the fault
}

}  // namespace
}  // namespace mark
