#pragma once
// The stroke database's element: a line, a circular arc or an elliptical arc, with a laser on/off
// flag (an element with the laser off is travel). Geometry is exact: arcs stay arcs through every
// affine transform — a circular arc under a non-uniform scale or a shear becomes an exact
// elliptical arc, never a polyline.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <variant>

#include "fonts/box.hpp"

namespace mark {

using Affine = Eigen::Affine2d;

struct Line {
  Point start;
  Point end;
};

// Circular arc: point(θ) = center + radius·(cos θ, sin θ), θ from start_angle to
// start_angle + sweep (radians). sweep > 0 runs counter-clockwise.
struct CircularArc {
  Point center;
  double radius;
  double start_angle;
  double sweep;
};

// Elliptical arc: point(θ) = center + R(rotation)·(rx·cos θ, ry·sin θ), θ from start_param to
// start_param + sweep (radians, the ellipse's eccentric-anomaly parameter). sweep > 0 runs
// counter-clockwise in the ellipse's own frame.
struct EllipticalArc {
  Point center;
  double rx;
  double ry;
  double rotation;
  double start_param;
  double sweep;
};

enum class ElementKind { line, arc, ellipse };

class Element {
 public:
  using Geometry = std::variant<Line, CircularArc, EllipticalArc>;

  Element(Geometry g, bool laser) : geometry_(g), laser_(laser) {}

  static Element line(const Point& a, const Point& b, bool laser = true);
  static Element arc(const Point& center, double radius, double start_angle, double sweep,
                     bool laser = true);
  // The circular arc from `start` to `end` with the given radius: the minor arc (sweep ≤ π)
  // unless `major`, turning counter-clockwise if `ccw`. Throws InputError if the chord is
  // longer than the diameter by more than 1e-9 relative.
  static Element arc_through(const Point& start, const Point& end, double radius, bool ccw,
                             bool major = false, bool laser = true);
  // The DXF/LFF bulge arc from `start` to `end`: bulge = tan(sweep/4), positive counter-clockwise.
  // A bulge of 0 gives a line.
  static Element bulge(const Point& start, const Point& end, double bulge, bool laser = true);
  static Element ellipse(const Point& center, double rx, double ry, double rotation,
                         double start_param, double sweep, bool laser = true);

  ElementKind kind() const { return static_cast<ElementKind>(geometry_.index()); }
  const Geometry& geometry() const { return geometry_; }
  bool laser() const { return laser_; }
  void set_laser(bool on) { laser_ = on; }

  // Point and unit tangent (direction of travel) at t ∈ [0, 1] of the element's own parameter.
  // For arcs the parameter is proportional to angle, for lines to length.
  Point point_at(double t) const;
  Point tangent_at(double t) const;
  Point start() const { return point_at(0.0); }
  Point end() const { return point_at(1.0); }

  // Exact length; elliptical arcs by adaptive Gauss–Legendre quadrature to 1e-12 relative.
  double length() const;
  // Length of the part between parameters t0 ≤ t1.
  double length_between(double t0, double t1) const;
  Box bounds() const;
  Element reversed() const;
  Element transformed(const Affine& transform) const;

 private:
  Geometry geometry_;
  bool laser_;
};

// Length of an elliptical arc between two parameter values (θ, not t).
double ellipse_arc_length(double rx, double ry, double theta0, double theta1);

// True when angle a (radians) lies on the sweep from `start` by `sweep` (either sign).
bool angle_on_sweep(double a, double start, double sweep);

}  // namespace mark
