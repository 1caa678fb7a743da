#pragma once
// Biarc fitting: a Bézier curve becomes a tangent-continuous chain of circular arcs within a
// distance tolerance. Arcs, not chords, because the galvo and the CNC both run arcs natively
// (G2/G3, the arc interpolator) and a biarc's error falls with the cube of the piece length where
// a chord's falls only with the square — far fewer elements for the same accuracy.
//
// Method (Bolton 1975; split at inflections and join point as in D. Lacko 2016, see
// shared/reference/fonts_cnc.md): split the cubic at its inflections, fit the equal-tangent-length
// biarc to each piece, measure the distance both ways by sampling, and halve the piece
// (de Casteljau) until it is within tolerance.
#include <limits>
#include <vector>

#include "fonts/element.hpp"

namespace mark {

struct CubicBezier {
  Point p0, p1, p2, p3;

  Point point_at(double t) const;
  Point derivative_at(double t) const;
  // The two halves at t (de Casteljau).
  std::pair<CubicBezier, CubicBezier> split(double t) const;
  // The exact cubic form of a quadratic (TrueType "conic") Bézier.
  static CubicBezier from_quadratic(const Point& p0, const Point& control, const Point& p2);
};

// Parameters in (0, 1) where the cubic's curvature changes sign, ascending (at most two).
std::vector<double> inflections(const CubicBezier& c);

// Distance from p to the curve (dense sampling refined by golden-section search).
double distance_to_cubic(const CubicBezier& c, const Point& p);
// Distance from p to an element's geometry (line segment or circular arc).
double distance_to_element(const Element& e, const Point& p);

// Appends lit elements approximating `c` so that every point of the fit lies within `tolerance`
// of the curve and every point of the curve within `tolerance` of the fit. Mostly circular arcs;
// a line where a piece is straight to within a thousandth of the tolerance. Appends nothing for a
// curve that is a single point. Stops once `out` holds `max_out` elements and returns false then
// (the fit is incomplete): a caller with an element budget pays for at most that many.
bool fit_biarcs(const CubicBezier& c, double tolerance, std::vector<Element>& out,
                std::size_t max_out = std::numeric_limits<std::size_t>::max());

}  // namespace mark
