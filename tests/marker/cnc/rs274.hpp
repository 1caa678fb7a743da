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

// Path to the rs274 wrapper, or empty when it is missing.
std::string rs274_path();
// Empty when rs274 is there; else why not and how to get it (one line).
std::string rs274_missing();

// Skips the calling test, with the reason, when rs274 is missing: the interpreter is an optional
// external tool (LinuxCNC, unpacked by scripts/fetch_rs274.sh, which scripts/setup.sh and so CI
// run), as umockdev is for the USB suite. CTest reports such a test as skipped, not failed.
#define REQUIRE_RS274()                                                                  \
  if (const std::string rs274_why = ::mark::test::rs274_missing(); !rs274_why.empty()) \
  GTEST_SKIP() << rs274_why

// Writes `program` to <build>/cnc_programs/<name>.ngc and interprets it, with `tool_table` as
// the tool table when given (LinuxCNC format, e.g. "T1 P1 D0.0315" — standalone rs274 reads the
// diameter in inches). Fails the calling test if rs274 is missing (a test that runs programs
// starts with REQUIRE_RS274()).
Rs274Run run_rs274(const std::string& program, const std::string& name, const std::string& tool_table = "");

}  // namespace mark::test
