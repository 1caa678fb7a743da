#pragma once
// A plan as a command-level device (a vector board with its own clock) takes it: device
// commands (driver/device_command.hpp) and one DevicePen.
//
// The board applies the pen's delays itself, so the host must not also put them in the plan:
// for the `delays` strategy the plan is made without its dwells (plan_for_device) and the
// delays go to the board as DevicePen parameters; for `blanking` the laser-off run-in, run-out
// and joining lines stay in the plan as jumps at their planned speed (a laser-off line at speed
// is what a board executes as a jump with its jump speed set) and the board gets the τ laser
// delays with zero jump / mark / polygon delays, so nothing waits between a run-in and its
// stroke. Lit arcs and ellipse arcs become chords within the device's chord tolerance unless the
// device takes circular arcs.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "driver/device.hpp"
#include "marker/layout/figure.hpp"
#include "marker/plan/plan.hpp"

namespace mark {

struct DeviceProgram {
  std::vector<DeviceCommand> commands;
  DevicePen pen;
  std::size_t chords = 0;     // lit arcs flattened into this many straight marks
};

// Whether a command-level device gets the host's own sample-level plan as timed moves
// (timed_moves.hpp) instead of the plan's elements: a pen that plans speeds (look-ahead,
// feed-forward) needs the speeds and the pre-compensated path only the host's locus has.
inline bool timed_on_board(const Pen& pen) { return pen.lookahead || pen.feed_forward(); }

// The plan a command-level device should receive for this figure and pen: the same strokes and
// blanking lines, without the host's delay dwells; for a timed pen, the host's plan itself.
Plan plan_for_device(const Figure& figure, const Pen& pen, StrokeOrder order);

// Refuses a point of device command `command` outside the device's field: DeviceFaultError
// (out_of_field) naming the point, the field and the command.
inline void check_in_field(const DeviceDescription& device, double x, double y, std::size_t command);
[[noreturn]] void refuse_outside_field(const DeviceDescription& device, double x, double y,
                                       std::size_t command);
inline void check_in_field(const DeviceDescription& device, double x, double y, std::size_t command) {
  // |v| ≤ half is false for NaN; infinities are above half, clamped so that an unbounded field
  // refuses them too.
  const double half = std::min(device.field_mm / 2, std::numeric_limits<double>::max());
  if (std::abs(x) <= half && std::abs(y) <= half) [[likely]]
    return;
  refuse_outside_field(device, x, y, command);
}

// The device pen for a host pen and its laser settings, at a device level: sample-level devices
// get the laser settings only (the host applies delays), command-level devices the delays too
// (but for a timed pen, whose locus has them).
DevicePen device_pen(const Pen& pen, const LaserSettings& laser, DeviceLevel level);

// Converts the plan. Every end point (and every chord point) is checked against the device's
// field before anything is returned: throws DeviceFaultError (out_of_field) naming the point.
DeviceProgram device_program(const Plan& plan, const LaserSettings& laser,
                             const DeviceDescription& device);

// The conversion in two steps, for ProgramStream (program_stream.hpp), which runs the second on
// a worker thread.
struct ProgramCount {
  std::size_t commands = 0;          // at least as many device commands as the plan commands
                                     // become (the program's leading pen command not included)
  std::vector<std::size_t> chords;   // each curve's chord count, in plan order
  bool inside_field = false;         // every point they can become lies in the field, with a
                                     // margin: converting them cannot be refused
};
// Counts plan commands [begin, end).
ProgramCount count_program(const Plan& plan, const DeviceDescription& device,
                           std::size_t begin = 0,
                           std::size_t end = std::numeric_limits<std::size_t>::max());
// Appends the plan's device commands to `out` (reserved for count.commands + 1 beforehand, so
// it never reallocates), calling `progress(n)` each time `every` more commands are in and once at
// the end. Throws as device_program does; commands before the refused point stay in `out`.
void convert_program(const Plan& plan, const DeviceDescription& device, const ProgramCount& count,
                     DeviceProgram& out, const std::function<void(std::size_t)>& progress,
                     std::size_t every);

// Ink: the lit length of the program's first `done` commands (all by default). Walked on demand
// (a job asks once, when it stopped early) rather than summed per command while converting:
// that cost a square root per ellipse chord and a second vector as long as the program.
double lit_length_mm(const DeviceProgram& program,
                     std::uint64_t done = std::numeric_limits<std::uint64_t>::max());

// Fraction of the program's ink (lit length) in its first `done` commands.
double ink_fraction(const DeviceProgram& program, std::uint64_t done);

}  // namespace mark
