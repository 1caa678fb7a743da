#pragma once
// The toolpath curve: a shape-preserving (monotone) cubic Hermite curve through the control
// points (Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980) 238; slopes by the weighted harmonic
// mean of Fritsch & Butland, the rule of Matlab's / SciPy's pchip).
//
// Why not the natural C² spline of the seed (cubic_spline.hpp): its second derivatives are
// global, so two knots nearly on top of each other at different depths (a single cell's exit on
// the surface 0.0015 cell before the next channel cell's entry 8 µm down) make a slope of
// thousands of µm per cell that swings the curve hundreds of µm past both (issue 23: −335 …
// +482 µm where the full cell is 40 µm). Merging knots by depth as well as distance only moves
// the threshold: any pair closer than the merge gap still rings. Here each knot's slope is set
// from its two neighbouring secants only, zero where they differ in sign (a local extremum —
// every cell centre and every lift point) and the harmonic mean otherwise, which Fritsch–Carlson
// show keeps each piece monotone: between any two knots the curve stays within their depths,
// so the stylus is never told to go deeper than the deepest control point the cells asked for.
// The curve is C¹ (the seed's spline is C²); its second derivative may step at a knot, which
// the head's drive filters see as a step in acceleration, not in velocity.
//
// The slope at a knot needs the knot after it, so the stream commits each piece once the knot
// two ahead of its start is in: constant memory, no windows to overlap.
#include <cstddef>
#include <vector>

namespace mark {

// Slope at a knot with secants d0 (from the knot before) and d1 (to the knot after) over
// intervals h0 and h1: 0 at an extremum, else the weighted harmonic mean.
double monotone_slope(double h0, double d0, double h1, double d1);

class MonotoneCurve {
 public:
  // Appends a knot; x must exceed the previous knot's x and both be finite.
  void push(double x, double y);
  // No more knots: the curve ends flat at the last one.
  void finish();

  // The curve is final on [first knot, committed_x()].
  double committed_x() const;
  bool finished() const { return finished_; }

  // One piece of the curve as a polynomial in t = x − x0: c0 + t(c1 + t(c2 + t·c3)).
  struct Segment {
    double x0 = 0, x1 = 0;
    double c0 = 0, c1 = 0, c2 = 0, c3 = 0;
    double operator()(double x) const {
      const double t = x - x0;
      return c0 + t * (c1 + t * (c2 + t * c3));
    }
  };
  // Sequential access: the piece holding x (x must not decrease between calls and must lie
  // within the committed range). Below the first knot and above the last the end value holds.
  Segment segment_at(double x);
  double eval(double x) { return segment_at(x)(x); }

  std::size_t knots() const { return base_ + x_.size(); }

 private:
  bool slope_known(std::size_t i) const;  // index from base_
  double slope(std::size_t i) const;
  void compact();

  std::vector<double> x_, y_;  // knots from index base_
  std::size_t base_ = 0;
  std::size_t segment_ = 0;  // evaluation cursor (from base_)
  bool finished_ = false;
};

}  // namespace mark
