#pragma once
// The machine-independent toolpath the CNC generators build and the G-code writer renders in a
// dialect: rapid, straight feed and circular-arc moves in millimetres, grouped into
// subprograms (one per distinct character, in the character's own coordinates) and a main
// sequence of moves and subprogram calls that place a subprogram at a position and rotation.
// A dialect that cannot call subprograms, or cannot rotate them, inlines the transformed body.
#include <Eigen/Core>
#include <string>
#include <variant>
#include <vector>

#include "fonts/element.hpp"

namespace mark {

enum class MoveKind { rapid, feed, arc };

// Cutter radius compensation switched on a move (G41/G42, or G40 to cancel). Only the
// protrusion contour passes use it, and only when the user asks for control-side compensation.
enum class CompSide { unchanged, left, right, cancel };

struct ToolMove {
  MoveKind kind = MoveKind::rapid;
  Eigen::Vector3d end{0, 0, 0};  // mm
  Point center{0, 0};            // arc centre (arcs only; arcs lie in the plane z = end.z)
  bool ccw = false;              // arcs: counter-clockwise seen from +z (G03)
  double feed_mm_min = 0;        // feed and arc moves
  CompSide comp = CompSide::unchanged;

  static ToolMove rapid(double x, double y, double z) { return {MoveKind::rapid, {x, y, z}}; }
  static ToolMove feed(double x, double y, double z, double f) {
    return {MoveKind::feed, {x, y, z}, {0, 0}, false, f};
  }
  static ToolMove arc(double x, double y, double z, const Point& c, bool ccw, double f) {
    return {MoveKind::arc, {x, y, z}, c, ccw, f};
  }
};

struct ToolSubprogram {
  std::string label;            // what it cuts, for comments: e.g. "A (U+0041)"
  std::vector<ToolMove> body;   // local coordinates; starts and ends at safe height
};

struct SubprogramCall {
  std::size_t sub = 0;
  Point origin{0, 0};           // where the subprogram's (0, 0) lands, mm
  double rotation_rad = 0;      // rotation of the subprogram about its origin
};

using ToolStep = std::variant<ToolMove, SubprogramCall>;

struct Toolpath {
  std::vector<ToolSubprogram> subs;
  std::vector<ToolStep> steps;  // the main program, after the preamble
  double safe_z_mm = 5;
  // Diameter for control-side cutter compensation (the D word), when any move switches it on.
  double comp_diameter_mm = 0;
};

// Subprogram coordinates → field coordinates for one call (translation after rotation).
ToolMove place_move(const ToolMove& move, const SubprogramCall& call);

// Every move of the toolpath in field coordinates, subprogram calls expanded.
std::vector<ToolMove> expand_moves(const Toolpath& toolpath);

// How much the tool travels without cutting: the XY length of the rapid moves from the first cut
// on (the way to the first cut depends on where the operator left the spindle), and how often it
// lifts out of the work (a rapid that rises from below the surface).
struct RapidTravel {
  double xy_mm = 0;
  std::size_t retracts = 0;
};
RapidTravel rapid_travel(const Toolpath& toolpath);

}  // namespace mark
