#pragma once
// Arc-length parametrisation of one elliptical arc, so the beam moves at uniform speed on it.
//
// Built once per ellipse: nodes that crowd where the ellipse bends sharply (equal steps of the
// tangent's direction, never more than 0.2 rad of the parameter apart), each with its exact arc
// length from the start (5-point Gauss–Legendre over each short node interval, the sum pinned to
// Element::length_between over the whole arc), its point, its unit tangent dP/ds and its
// curvature vector d²P/ds². Between two nodes the point is the quintic Hermite interpolant in
// arc length of those exact values and derivatives: its error falls with the sixth power of the
// tangent's turn per interval (< 1e-9 of the local radius here), so the samples need no Newton
// iteration, no quadrature and no trigonometric call — a Horner polynomial per coordinate.
#include <cstddef>
#include <vector>

#include "fonts/element.hpp"

namespace mark {

class EllipseTable {
 public:
  // Rebuilds the table for `ellipse` (an ElementKind::ellipse element). Reuses storage.
  void build(const Element& ellipse);

  double length() const { return nodes_.back().s; }
  std::size_t nodes() const { return nodes_.size(); }

  // The point at arc length s ∈ [0, length()] from the arc's start. `node` is a cursor: lookups
  // at increasing s walk forward from it (start it at 0).
  Point point_at(double s, std::size_t& node) const {
    const Node& a = find(s, node);
    const double t = (s - a.s) * a.inv_len;
    return {horner(a.c[0], t), horner(a.c[1], t)};
  }

  // The point, the unit tangent dP/ds and (WithCurvature) the curvature vector d²P/ds² at arc
  // length s: the interpolant and its derivatives, for feed-forward, which needs the path's
  // velocity and acceleration. Same cursor as point_at.
  template <bool WithCurvature = true>
  void frame_at(double s, std::size_t& node, Point& p, Point& tangent, Point& curvature) const {
    const Node& a = find(s, node);
    const double t = (s - a.s) * a.inv_len, il = a.inv_len;
    p = {horner(a.c[0], t), horner(a.c[1], t)};
    tangent = {derivative(a.c[0], t) * il, derivative(a.c[1], t) * il};
    if constexpr (WithCurvature)
      curvature = {second_derivative(a.c[0], t) * il * il, second_derivative(a.c[1], t) * il * il};
  }

 private:
  struct Node {
    double s = 0;             // arc length from the start
    double inv_len = 0;       // 1 / length of the interval starting here
    double p[2] = {0, 0};     // the point
    double tan[2] = {0, 0};   // dP/ds: the unit tangent in the direction of travel
    double curv[2] = {0, 0};  // d²P/ds²: the curvature vector
    // The interval's quintic Hermite interpolant in the power basis of t = (s − s_node)/len,
    // per coordinate: P(t) = c0 + c1·t + … + c5·t⁵ (Horner: five multiply-adds a sample).
    double c[2][6] = {};
  };
  static double horner(const double (&c)[6], double t) {
    return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
  }
  static double derivative(const double (&c)[6], double t) {
    return c[1] + t * (2 * c[2] + t * (3 * c[3] + t * (4 * c[4] + t * 5 * c[5])));
  }
  static double second_derivative(const double (&c)[6], double t) {
    return 2 * c[2] + t * (6 * c[3] + t * (12 * c[4] + t * 20 * c[5]));
  }
  const Node& find(double s, std::size_t& node) const {
    const std::size_t last = nodes_.size() - 2;
    if (s < nodes_[node].s) node = 0;
    while (node < last && s > nodes_[node + 1].s) ++node;
    return nodes_[node];
  }
  std::vector<Node> nodes_;
};

}  // namespace mark
