#pragma once
// A milling machine's envelope, in place of the galvo's field: the stock the letters are cut
// into and the machine's travel. A G-code program is checked against it before it is written:
// every cut — the tool's footprint at the surface, not only its centre — must lie on the stock,
// and the whole program (rapids included) must fit the travel; a refusal says which side is
// left and by how much.
#include <optional>

#include "fonts/box.hpp"
#include "marker/cnc/toolpath.hpp"

namespace mark {

struct MachineEnvelope {
  std::optional<Box> stock;  // work coordinates, mm; none: no stock check
  double travel_x_mm = 10000;  // the largest program extent the machine can run, mm
  double travel_y_mm = 10000;
};

// What a toolpath occupies, mm: where it cuts (each cutting move's footprint at the surface)
// and where it goes at all (every move's tool-centre path).
struct ToolpathExtent {
  Box cuts;
  Box moves;
};

// How far a cut at height z (< 0) reaches around the tool centre at the surface: the tool radius
// for a flat or ball tool, depth · tan(half angle) for a V-bit.
struct CutFootprint {
  double tool_radius_mm = 0;
  double v_half_angle_rad = 0;  // > 0: a V-bit
  double radius_at(double z_mm) const;
};

ToolpathExtent toolpath_extent(const Toolpath& toolpath, const CutFootprint& footprint);

// Throws InputError when the cuts leave the stock (naming every side left and by how much) or
// the program is wider or taller than the travel. `remedy` ends the message.
void require_within(const ToolpathExtent& extent, const MachineEnvelope& envelope, const char* remedy);

}  // namespace mark
