#pragma once
// Red-pointer framing: what the operator sees traced on the part before marking, so it can be
// aligned — the job's bounding box, its convex hull, or the strokes themselves. Closed
// polylines (mm, field frame) for a command-level device to trace with the laser off.
#include <string_view>
#include <vector>

#include "driver/vec2.hpp"
#include "marker/layout/figure.hpp"

namespace mark {

enum class FrameShape {
  box,     // the bounding rectangle of everything lit
  hull,    // the convex hull of everything lit (tighter on rotated or circular text)
  strokes  // every lit stroke, arcs flattened to the tolerance
};

// "box", "hull" or "strokes"; throws InputError naming the value otherwise.
FrameShape parse_frame_shape(std::string_view name);

// The polylines to trace. Throws InputError for a figure with nothing lit.
std::vector<std::vector<Vec2>> frame_paths(const Figure& figure, FrameShape shape,
                                           double chord_tolerance_mm = 0.02);

}  // namespace mark
