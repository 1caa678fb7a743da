#pragma once
// The device-command vocabulary: what a command-level device (a vector board with its own
// clock) receives instead of 10 µs samples. marker/ converts its plan into these; each device
// converts them into its own wire format at the edge (LMC: JumpTo / MarkTo / DelayTime and
// speed words, in 16-bit field units).
//
// Coordinates are the field frame in mm (origin at the field centre). A command starts where
// the previous one ended; the first starts where begin_job left the mirrors (the field centre).
// A speed of 0 means the current pen's speed for that kind of move. The pen's delays (laser
// on/off, jump, mark, polygon) are applied by the device itself, not by extra commands.
//
// A timed move (duration_s > 0) takes that long on the device's clock: the device picks the
// speed that makes it so from the distance it actually travels (its own units, rounded). The host
// sends these when it has planned the motion itself (look-ahead, feed-forward): the 10 µs locus
// cut into short straight moves, each as long in time as the samples it replaces, so the board's
// constant-speed moves retrace the planned speeds (marker/job/timed_moves.hpp).
#include <cstdint>

namespace mark {

enum class DeviceOp : std::uint8_t {
  pen,    // select pen `pen` of the job header (speeds, delays, laser settings)
  jump,   // move to (x, y) with the laser off at speed_mm_s (0: the pen's jump speed). A
          // blanking run-in / run-out / join is a jump at the marking speed.
  mark,   // move to (x, y) in a straight line with the laser on at speed_mm_s (0: marking speed)
  arc,    // circular arc with the laser on from the current point around (cx, cy) by sweep_rad
          // (counter-clockwise positive), ending at (x, y). Only to devices with arcs.
  dwell   // hold still for dwell_s, laser on if `laser` (a dot), off otherwise (a delay)
};

struct DeviceCommand {
  DeviceOp op = DeviceOp::jump;
  bool laser = false;          // dwell only
  std::uint16_t pen = 0;       // op == pen
  double x_mm = 0, y_mm = 0;   // end point of jump, mark, arc
  double cx_mm = 0, cy_mm = 0; // arc centre
  double sweep_rad = 0;        // arc sweep
  double speed_mm_s = 0;       // jump, mark, arc; 0 = the pen's
  double dwell_s = 0;          // dwell
  double duration_s = 0;       // jump, mark: a timed move (above), speed_mm_s its mean speed
  double power_fraction = 1;   // a timed mark: its share of the pen's power (look-ahead's
                               // power ∝ speed, so the dose per mm holds where it slows)

  static DeviceCommand select_pen(std::uint16_t index) {
    DeviceCommand c;
    c.op = DeviceOp::pen;
    c.pen = index;
    return c;
  }
  static DeviceCommand jump_to(double x, double y, double speed = 0) {
    DeviceCommand c;
    c.op = DeviceOp::jump;
    c.x_mm = x, c.y_mm = y, c.speed_mm_s = speed;
    return c;
  }
  static DeviceCommand mark_to(double x, double y, double speed = 0) {
    DeviceCommand c;
    c.op = DeviceOp::mark;
    c.x_mm = x, c.y_mm = y, c.speed_mm_s = speed;
    return c;
  }
  // A move of `duration_s` with the laser on (mark) or off (jump), at its mean speed.
  static DeviceCommand timed_move(bool laser_on, double x, double y, double speed, double duration_s,
                                  double power_fraction = 1) {
    DeviceCommand c = laser_on ? mark_to(x, y, speed) : jump_to(x, y, speed);
    c.duration_s = duration_s;
    c.power_fraction = power_fraction;
    return c;
  }
  static DeviceCommand arc_to(double x, double y, double cx, double cy, double sweep,
                              double speed = 0) {
    DeviceCommand c;
    c.op = DeviceOp::arc;
    c.x_mm = x, c.y_mm = y, c.cx_mm = cx, c.cy_mm = cy, c.sweep_rad = sweep, c.speed_mm_s = speed;
    return c;
  }
  static DeviceCommand dwell_for(double seconds, bool laser_on) {
    DeviceCommand c;
    c.op = DeviceOp::dwell;
    c.dwell_s = seconds, c.laser = laser_on;
    return c;
  }
};

}  // namespace mark
