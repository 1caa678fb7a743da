#pragma once
// What the user sets for a CNC engraving job, shared by the depression and protrusion
// generators: tool, depths, heights, feeds and how arcs are approximated. Millimetres and
// millimetres per minute; depths are positive numbers measured down from the surface (z = 0).
#include <vector>

#include "marker/cnc/arc_spline.hpp"

namespace mark {

struct CutSettings {
  double tool_diameter_mm = 1.0;
  double depth_mm = 0.2;          // final depth below the surface
  double depth_per_pass_mm = 0;   // at most this much per pass; 0 = the full depth in one pass
  double safe_z_mm = 5.0;         // rapid moves happen at this height
  double feed_mm_min = 300;
  double plunge_feed_mm_min = 100;
  ArcSplineOptions arcs;
};

// Throws InputError naming the setting when a value is impossible (non-positive tool, depth,
// feed; safe height not above the surface; a tolerance of zero).
void validate(const CutSettings& settings);

// z of each pass, top to bottom: equal steps of at most depth_per_pass down to −depth.
std::vector<double> pass_depths(const CutSettings& settings);

}  // namespace mark
