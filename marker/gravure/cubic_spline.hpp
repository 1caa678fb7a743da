#pragma once
// The curve fitter of the seed (block 48; Numerical Recipes in C §3.3): the cubic spline through
// the control points, C² everywhere, solved for the second derivatives M_i at the knots,
//
//   h_{i−1} M_{i−1} + 2 (h_{i−1} + h_i) M_i + h_i M_{i+1} = 6 [(y_{i+1} − y_i)/h_i − (y_i − y_{i−1})/h_{i−1}],
//
// a symmetric, diagonally dominant tridiagonal system solved with Eigen's sparse LDLᵀ
// (natural ordering: no fill-in, linear time).
//
// The toolpath no longer uses it (issue 23: its global second derivatives swing the curve far
// past two nearly coincident knots at different depths; see monotone_curve.hpp). It stays as the
// seed's reference curve the tests compare the monotone one with.
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <span>
#include <vector>

namespace mark {

class SplineSolver {
 public:
  // Fills m[1 .. n−2] for the knots (x strictly increasing, n ≥ 3) given m[0] and m[n−1].
  void solve(std::span<const double> x, std::span<const double> y, std::span<double> m);

 private:
  using Matrix = Eigen::SparseMatrix<double>;
  Matrix a_;
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt_;
  Eigen::Index size_ = -1;
  Eigen::VectorXd rhs_;
};

// Value of the cubic on [x0, x1] with end values y and end second derivatives m, at x.
inline double spline_value(double x0, double x1, double y0, double y1, double m0, double m1, double x) {
  const double h = x1 - x0, a = (x1 - x) / h, b = (x - x0) / h;
  return a * y0 + b * y1 + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * (h * h) / 6;
}

// A natural cubic spline through all the knots at once (tests, short paths).
class CubicSpline {
 public:
  CubicSpline(std::vector<double> x, std::vector<double> y);
  double operator()(double x) const;
  const std::vector<double>& second_derivatives() const { return m_; }

 private:
  std::vector<double> x_, y_, m_;
};

}  // namespace mark
