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
// iteration, no quadrature and no trigonometric call — about thirty flops each.
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
    const std::size_t last = nodes_.size() - 2;
    if (s < nodes_[node].s) node = 0;
    while (node < last && s > nodes_[node + 1].s) ++node;
    const Node& a = nodes_[node];
    const Node& b = nodes_[node + 1];
    const double len = b.s - a.s;
    const double t = (s - a.s) * a.inv_len, t2 = t * t, t3 = t2 * t;
    const double h5 = t3 * (10 - 15 * t + 6 * t2), h0 = 1 - h5;
    const double h1 = len * t * (1 + t2 * (-6 + t * (8 - 3 * t)));
    const double h4 = len * t3 * (-4 + t * (7 - 3 * t));
    const double h2 = len * len * t2 * (0.5 + t * (-1.5 + t * (1.5 - 0.5 * t)));
    const double h3 = len * len * t3 * (0.5 + t * (-1 + 0.5 * t));
    return {h0 * a.p[0] + h5 * b.p[0] + h1 * a.tan[0] + h4 * b.tan[0] + h2 * a.curv[0] + h3 * b.curv[0],
            h0 * a.p[1] + h5 * b.p[1] + h1 * a.tan[1] + h4 * b.tan[1] + h2 * a.curv[1] + h3 * b.curv[1]};
  }

  // The point, the unit tangent dP/ds and the curvature vector d²P/ds² at arc length s: the
  // interpolant and its derivatives (for feed-forward, which needs the path's velocity and
  // acceleration). Same cursor as point_at.
  void frame_at(double s, std::size_t& node, Point& p, Point& tangent, Point& curvature) const {
    const std::size_t last = nodes_.size() - 2;
    if (s < nodes_[node].s) node = 0;
    while (node < last && s > nodes_[node + 1].s) ++node;
    const Node& a = nodes_[node];
    const Node& b = nodes_[node + 1];
    const double len = b.s - a.s, il = a.inv_len;
    const double t = (s - a.s) * il, t2 = t * t, t3 = t2 * t;
    // Quintic Hermite basis (as in point_at) and its first and second derivatives in t.
    const double h5 = t3 * (10 - 15 * t + 6 * t2), h0 = 1 - h5;
    const double d5 = 30 * t2 * (1 - t) * (1 - t), dd5 = 60 * t * (1 - t) * (1 - 2 * t);
    const double h1 = len * t * (1 + t2 * (-6 + t * (8 - 3 * t)));
    const double d1 = len * (1 + t2 * (-18 + t * (32 - 15 * t)));
    const double dd1 = len * t * (-36 + t * (96 - 60 * t));
    const double h4 = len * t3 * (-4 + t * (7 - 3 * t));
    const double d4 = len * t2 * (-12 + t * (28 - 15 * t));
    const double dd4 = len * t * (-24 + t * (84 - 60 * t));
    const double h2 = len * len * t2 * (0.5 + t * (-1.5 + t * (1.5 - 0.5 * t)));
    const double d2 = len * len * t * (1 + t * (-4.5 + t * (6 - 2.5 * t)));
    const double dd2 = len * len * (1 + t * (-9 + t * (18 - 10 * t)));
    const double h3 = len * len * t3 * (0.5 + t * (-1 + 0.5 * t));
    const double d3 = len * len * t2 * (1.5 + t * (-4 + 2.5 * t));
    const double dd3 = len * len * t * (3 + t * (-12 + 10 * t));
    double out[3][2];
    for (int k = 0; k < 2; ++k) {
      out[0][k] = h0 * a.p[k] + h5 * b.p[k] + h1 * a.tan[k] + h4 * b.tan[k] + h2 * a.curv[k] + h3 * b.curv[k];
      out[1][k] = (d5 * (b.p[k] - a.p[k]) + d1 * a.tan[k] + d4 * b.tan[k] + d2 * a.curv[k] + d3 * b.curv[k]) * il;
      out[2][k] = (dd5 * (b.p[k] - a.p[k]) + dd1 * a.tan[k] + dd4 * b.tan[k] + dd2 * a.curv[k] + dd3 * b.curv[k]) * il * il;
    }
    p = {out[0][0], out[0][1]};
    tangent = {out[1][0], out[1][1]};
    curvature = {out[2][0], out[2][1]};
  }

 private:
  struct Node {
    double s = 0;             // arc length from the start
    double inv_len = 0;       // 1 / length of the interval starting here
    double p[2] = {0, 0};     // the point
    double tan[2] = {0, 0};   // dP/ds: the unit tangent in the direction of travel
    double curv[2] = {0, 0};  // d²P/ds²: the curvature vector
  };
  std::vector<Node> nodes_;
};

}  // namespace mark
