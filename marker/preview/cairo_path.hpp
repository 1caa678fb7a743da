#pragma once
// Elements as Cairo path segments: lines as lines, circular arcs as native Cairo arcs, elliptical
// arcs as arcs under a scaled, rotated frame — exact, nothing flattened here.
#include <cairo.h>

#include "fonts/element.hpp"

namespace mark {

// Appends the element to the current path; starts a new sub-path (move_to) unless the current
// point already is the element's start.
void append_element(cairo_t* cr, const Element& element);

}  // namespace mark
