#include "marker/cnc/tool/circle_fit.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "base/error.hpp"

namespace mark {

Circle fit_circle_algebraic(const std::vector<Point>& pts) {
  if (pts.size() < 3) throw InputError("circle fit: need at least 3 edge points, got " + std::to_string(pts.size()));
  // Centred coordinates keep the normal equations well conditioned.
  Point mean(0, 0);
  for (const Point& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Eigen::MatrixXd a(pts.size(), 3);
  Eigen::VectorXd b(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Point q = pts[i] - mean;
    a(i, 0) = q.x();
    a(i, 1) = q.y();
    a(i, 2) = 1;
    b(i) = -q.squaredNorm();
  }
  // x² + y² + D·x + E·y + F = 0
  const Eigen::Vector3d def = a.colPivHouseholderQr().solve(b);
  const Point c(-def(0) / 2, -def(1) / 2);
  const double r2 = c.squaredNorm() - def(2);
  if (!(r2 > 0) || !std::isfinite(r2)) throw InputError("circle fit: the edge points do not lie on a circle");
  return {c + mean, std::sqrt(r2)};
}

Circle fit_circle_geometric(const std::vector<Point>& pts, const Circle& start) {
  if (pts.size() < 3) return start;
  Eigen::Vector3d x(start.center.x(), start.center.y(), start.radius);
  for (int it = 0; it < 50; ++it) {
    Eigen::MatrixXd j(pts.size(), 3);
    Eigen::VectorXd r(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Point d = pts[i] - Point(x(0), x(1));
      const double n = std::max(d.norm(), 1e-12);
      r(i) = n - x(2);
      j(i, 0) = -d.x() / n;
      j(i, 1) = -d.y() / n;
      j(i, 2) = -1;
    }
    const Eigen::Vector3d step = (j.transpose() * j).ldlt().solve(-j.transpose() * r);
    if (!step.allFinite()) break;
    x += step;
    if (step.norm() < 1e-12 * std::max(1.0, x(2))) break;
  }
  return {Point(x(0), x(1)), std::abs(x(2))};
}

}  // namespace mark
