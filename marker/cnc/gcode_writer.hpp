#pragma once
// Toolpath → G-code text in one dialect. Every coordinate is rounded to the output precision
// (mm: 4 decimals, inch: 5) and arcs get their I/J from the rounded start and end points and the
// exact centre moved onto the rounded chord's bisector, so the interpreter's start and end radii
// differ by far less than 0.005 mm; an arc that rounds to nothing is dropped, never written as
// a full circle.
#include <cstddef>
#include <string>

#include "base/progress.hpp"
#include "marker/cnc/gcode_options.hpp"
#include "marker/cnc/toolpath.hpp"

namespace mark {

struct GcodeStats {
  std::size_t lines = 0;
  std::size_t rapids = 0;
  std::size_t feeds = 0;
  std::size_t arcs = 0;
  std::size_t calls = 0;            // subprogram calls written
  std::size_t inlined = 0;          // occurrences written out in full instead of called
  double max_arc_radius_error_mm = 0;  // largest |r_end − r_start| the controller will see
};

// Throws InputError when the dialect cannot express the toolpath (cutter compensation in plain).
// `progress` hears every few thousand lines and may stop the writing (Interrupted).
std::string write_gcode(const Toolpath& toolpath, const GcodeOptions& options,
                        GcodeStats* stats = nullptr, const Progress& progress = Progress::none());

}  // namespace mark
