#pragma once
// The lag test pattern for a command-level board (a vector board such as the LMC runs its own
// clock, so it takes commands, not samples): the lines, holds and powers of
// lag_pattern_samples as device commands. One pen per speed — that marking speed, the power in
// the same proportion to the speed, and every delay zero, so the board adds no delay that the
// fit would read as lag — then per line a jump to its start, an unlit dwell while the head
// settles, a mark along it and an unlit dwell after.
#include <vector>

#include "driver/device.hpp"
#include "marker/head/lag_pattern.hpp"

namespace mark {

struct LagProgram {
  JobHeader header;                     // pens and lit paths (a simulator sizes its dose from them)
  std::vector<DeviceCommand> commands;
};

// For `device` (its longest dwell splits the holds) with the pen's laser settings at the
// fastest line (`laser.power_pct` there, less on slower lines). Throws InputError when the
// pattern leaves the device's field or a line is faster than the device marks.
LagProgram lag_pattern_program(const LagPattern& pattern, const LaserSettings& laser,
                               const DeviceDescription& device);

}  // namespace mark
