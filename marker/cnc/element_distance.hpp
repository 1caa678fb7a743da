#pragma once
// Distance from a point to a line segment or a circular arc, exact. Used to check how far an
// arc spline strays from the curve it replaces, and by the tests that compare the interpreter's
// moves with the Figure.
#include "fonts/element.hpp"

namespace mark {

double distance_to_segment(const Point& p, const Point& a, const Point& b);
double distance_to_arc(const Point& p, const CircularArc& arc);
// Lines and circular arcs exactly; elliptical arcs by parameter samples refined with a
// golden-section search (to well below a nanometre).
double distance_to_element(const Point& p, const Element& element);

}  // namespace mark
