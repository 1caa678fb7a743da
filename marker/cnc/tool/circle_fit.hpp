#pragma once
// Least-squares circles through edge points: the algebraic (Kåsa) fit, linear and always
// defined, as the start for the geometric fit (Gauss–Newton on the distances |p − c| − r),
// which is the one whose radius means what a machinist means by it.
#include <vector>

#include "fonts/box.hpp"

namespace mark {

struct Circle {
  Point center{0, 0};
  double radius = 0;
};

// Throws InputError when fewer than 3 points or the points are collinear.
Circle fit_circle_algebraic(const std::vector<Point>& points);
// Starting from `start`; returns `start` unchanged for fewer than 3 points.
Circle fit_circle_geometric(const std::vector<Point>& points, const Circle& start);

}  // namespace mark
