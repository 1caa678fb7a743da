#pragma once
// Drawing commands: what the planner hands the locus generator. A command is one element
// traversed at one constant speed (jump, mark line, mark circular arc, mark elliptical arc) or a
// dwell (the mirrors hold still for a number of ticks). Blanking lines are line commands with the
// laser off; `role` says why a command exists, so tests and previews can tell them apart.
//
// Look-ahead planning (marker/plan/speed_plan.hpp) gives a move a speed profile instead of one
// speed: it is entered at entry_speed_mm_s, speeds up at accel_mm_s2 to at most speed_mm_s and
// slows down at decel_mm_s2 to exit_speed_mm_s at its end (a trapezoid in time; speed_profile.hpp).
// Its lit power then follows its speed — power = speed / full_power_speed_mm_s of the pen's
// power — so the pulses stay evenly spaced and the dose per mm constant. A command-level device
// maps these fields to its own ramps: the entry and exit speeds are the speeds at the element's
// ends, continuous between consecutive planned moves.
#include <cstdint>
#include <string_view>

#include "fonts/element.hpp"

namespace mark {

// A move shorter than this is a point: the speed plan and the locus generators skip it alike.
inline constexpr double kMinLength_mm = 1e-9;

enum class CommandKind { jump, line, arc, ellipse, dwell };

enum class CommandRole {
  stroke,      // a lit element of the figure
  jump,        // travel between strokes, laser off, at jump speed
  run_in,      // blanking: extension backward from a lit element's start, laser off
  run_out,     // blanking: extension forward from a lit element's end, laser off
  blank_join,  // blanking: the line joining a run-out to the next run-in, laser off
  delay        // a dwell: jump / mark / polygon delay
};

struct Command {
  CommandKind kind;
  CommandRole role;
  Element path;                // for a dwell: a zero-length line at the dwell point
  double speed_mm_s = 0;       // jumps and marks
  std::uint32_t dwell_ticks = 0;
  // The path's length, computed once (an ellipse's takes a quadrature); 0 for a dwell.
  double length = 0;
  // Speed profile (look-ahead); accel_mm_s2 = 0: constant speed_mm_s over the whole path.
  double entry_speed_mm_s = 0;
  double exit_speed_mm_s = 0;
  double accel_mm_s2 = 0;
  double decel_mm_s2 = 0;
  // Lit power ∝ speed, full power at this speed; 0: constant power.
  double full_power_speed_mm_s = 0;
  // A lit move is dark wherever its speed is below this (the last and first micrometres of a
  // stop): where a beam slows to a stop, a model error turns it around while the power is
  // still on, and the dwell burns in; 0: lit throughout.
  double min_lit_speed_mm_s = 0;

  bool laser() const { return path.laser(); }
  Point start() const { return path.start(); }
  Point end() const { return path.end(); }
  double length_mm() const { return length; }
  bool planned() const { return accel_mm_s2 > 0; }
  // Time to traverse the path (0 for a dwell: its time is dwell_ticks ticks).
  double move_duration_s() const;

  static Command jump(const Point& from, const Point& to, double speed_mm_s);
  // A lit (or, for blanking lines, unlit) element at the given speed; kind follows the element.
  static Command mark(const Element& element, double speed_mm_s, CommandRole role);
  // The same with the element's length already known.
  static Command mark(const Element& element, double speed_mm_s, CommandRole role,
                      double length_mm);
  static Command dwell(const Point& at, std::uint32_t ticks, bool laser);
};

std::string_view to_string(CommandKind kind);
std::string_view to_string(CommandRole role);

}  // namespace mark
