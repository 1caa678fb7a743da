#pragma once
// Arc-length parametrisation of one elliptical arc, so the beam moves at uniform speed on it.
//
// Built once per ellipse: nodes at equal steps of the tangent's direction (so they crowd where
// the ellipse bends sharply and thin out where it is flat), with the exact arc length from the
// start to each node summed from Element::length_between over the node intervals. Between two
// nodes the arc length S(θ) is the quintic Hermite interpolant of its exact value, slope |P'(θ)|
// and curvature of the slope; a sample at arc length s then takes a few Newton steps on that
// polynomial (starting from the previous sample) and one sincos — no quadrature per sample.
#include <cmath>
#include <cstddef>
#include <vector>

#include "fonts/element.hpp"

namespace mark {

class EllipseTable {
 public:
  // Where the previous lookup ended; lookups at increasing s walk forward from it.
  struct Cursor {
    std::size_t node = 0;
    double x = 0;  // position inside the node interval, 0..1
  };

  // Rebuilds the table for `ellipse` (an ElementKind::ellipse element). Reuses storage.
  void build(const Element& ellipse);

  double length() const { return s_.back(); }
  std::size_t nodes() const { return s_.size(); }
  // Eccentric-anomaly parameter at arc length s ∈ [0, length()] from the arc's start.
  double theta_at(double s, Cursor& cursor) const;
  double theta_at(double s) const {
    Cursor c;
    return theta_at(s, c);
  }
  Point point_at(double theta) const {
    const double x = rx_ * std::cos(theta), y = ry_ * std::sin(theta);
    return {cx_ + rc_ * x - rs_ * y, cy_ + rs_ * x + rc_ * y};
  }

 private:
  double cx_ = 0, cy_ = 0, rx_ = 0, ry_ = 0, rc_ = 1, rs_ = 0;
  double th0_ = 0;              // θ at the arc's start
  double sign_ = 1;             // direction of the sweep
  std::vector<double> phi_;     // |θ − start| at each node (increasing)
  std::vector<double> s_;       // arc length at each node
  std::vector<double> d1_;      // dS/dφ = |P'(θ)|
  std::vector<double> d2_;      // d²S/dφ²
};

}  // namespace mark
