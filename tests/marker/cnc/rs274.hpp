#pragma once
// Test support: runs LinuxCNC's standalone interpreter rs274 (unpacked by scripts/fetch_rs274.sh)
// on a program and parses the canonical machine calls it prints into moves in millimetres, in
// the work frame (the G5x and G92/G52 offsets the interpreter announces are added back).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "fonts/element.hpp"

namespace mark::test {

struct CanonMove {
  enum Kind { traverse, feed, arc } kind = traverse;
  Eigen::Vector3d start{0, 0, 0}, end{0, 0, 0};
  Point center{0, 0};
  int turn = 0;  // arcs: +1 counter-clockwise, −1 clockwise
  // The XY path of a feed or arc move as an element (lines and circular arcs).
  Element path() const;
};

struct Rs274Run {
  int exit_code = -1;
  std::string output;  // canonical calls (stdout)
  std::string errors;  // stderr: the interpreter's message and the offending line on failure
  std::vector<CanonMove> moves;
  std::string file;    // where the program was written
};

// Path to the rs274 wrapper; fails the calling test (with how to get it) when missing.
std::string rs274_path();

// Writes `program` to <build>/cnc_programs/<name>.ngc and interprets it, with `tool_table` as
// the tool table when given (LinuxCNC format, e.g. "T1 P1 D0.0315" — standalone rs274 reads the
// diameter in inches).
Rs274Run run_rs274(const std::string& program, const std::string& name, const std::string& tool_table = "");

}  // namespace mark::test
