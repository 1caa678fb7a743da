#pragma once
// The curve fitter of the seed (block 48; Numerical Recipes in C §3.3): the cubic spline through
// the control points, C² everywhere, solved for the second derivatives M_i at the knots,
//
//   h_{i−1} M_{i−1} + 2 (h_{i−1} + h_i) M_i + h_i M_{i+1} = 6 [(y_{i+1} − y_i)/h_i − (y_i − y_{i−1})/h_{i−1}],
//
// a symmetric, diagonally dominant tridiagonal system solved with Eigen's sparse LDLᵀ
// (natural ordering: no fill-in, linear time). The stream of a whole cylinder has millions of
// knots, so StreamingSpline solves it in overlapping windows: each window starts from the last
// committed M (exact C² continuity at the seam) and looks `overlap` knots ahead with a natural
// end there; the influence of that artificial end decays by at least half per knot (the
// diagonal is twice the off-diagonals), so with 32 knots of look-ahead the committed M differ
// from the whole-stream solution by < 1e−9 of the curve's scale.
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cstddef>
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

// The natural spline of an unbounded stream of knots, committed window by window.
class StreamingSpline {
 public:
  explicit StreamingSpline(std::size_t window = 512, std::size_t overlap = 32);

  // Appends a knot; x must exceed the previous knot's x.
  void push(double x, double y);
  // No more knots: the last one gets the natural end condition.
  void finish();

  // The spline is final on [first knot, committed_x()].
  double committed_x() const;
  bool finished() const { return finished_; }

  // One piece of the spline as a polynomial in t = x − x0: c0 + t(c1 + t(c2 + t·c3)).
  struct Segment {
    double x0 = 0, x1 = 0;
    double c0 = 0, c1 = 0, c2 = 0, c3 = 0;
    double operator()(double x) const {
      const double t = x - x0;
      return c0 + t * (c1 + t * (c2 + t * c3));
    }
  };
  // Sequential access: the piece holding x (x must not decrease between calls and must lie
  // within the committed range). Below the first knot and above the last the end value holds
  // (a constant piece).
  Segment segment_at(double x);
  double eval(double x) { return segment_at(x)(x); }

  std::size_t knots() const { return base_ + x_.size(); }

 private:
  void solve_window(bool to_end);
  void compact();

  std::size_t window_, overlap_;
  SplineSolver solver_;
  std::vector<double> x_, y_, m_;  // knots from index base_; m_ valid for [0, committed_)
  std::size_t base_ = 0;
  std::size_t committed_ = 0;      // knots (from base_) whose M are final
  std::size_t segment_ = 0;        // evaluation cursor (from base_)
  bool finished_ = false;
  std::vector<double> scratch_m_;
};

}  // namespace mark
