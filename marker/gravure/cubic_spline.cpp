#include "marker/gravure/cubic_spline.hpp"

#include <algorithm>
#include <stdexcept>

namespace mark {

void SplineSolver::solve(std::span<const double> x, std::span<const double> y, std::span<double> m) {
  const std::size_t n = x.size();
  if (n < 3) return;
  const Eigen::Index k = static_cast<Eigen::Index>(n - 2);
  if (k != size_) {
    // The lower triangle's pattern: column j holds the diagonal and the entry below it.
    std::vector<Eigen::Triplet<double>> t;
    for (Eigen::Index j = 0; j < k; ++j) {
      t.emplace_back(j, j, 1.0);
      if (j + 1 < k) t.emplace_back(j + 1, j, 0.0);
    }
    a_.resize(k, k);
    a_.setFromTriplets(t.begin(), t.end());
    a_.makeCompressed();
    ldlt_.analyzePattern(a_);
    rhs_.resize(k);
    size_ = k;
  }
  double* v = a_.valuePtr();
  for (Eigen::Index j = 0; j < k; ++j) {
    const std::size_t i = static_cast<std::size_t>(j) + 1;  // knot of this row
    const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    *v++ = 2 * (h0 + h1);
    if (j + 1 < k) *v++ = h1;
    rhs_[j] = 6 * ((y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0);
  }
  rhs_[0] -= (x[1] - x[0]) * m[0];
  rhs_[k - 1] -= (x[n - 1] - x[n - 2]) * m[n - 1];
  ldlt_.factorize(a_);
  if (ldlt_.info() != Eigen::Success) throw std::runtime_error("spline: knots are not strictly increasing");
  const Eigen::VectorXd sol = ldlt_.solve(rhs_);
  for (Eigen::Index j = 0; j < k; ++j) m[static_cast<std::size_t>(j) + 1] = sol[j];
}

CubicSpline::CubicSpline(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)), m_(x_.size(), 0.0) {
  if (x_.size() != y_.size() || x_.empty()) throw std::invalid_argument("spline: needs matching, non-empty knots");
  for (std::size_t i = 1; i < x_.size(); ++i)
    if (!(x_[i] > x_[i - 1])) throw std::invalid_argument("spline: knots must be strictly increasing");
  SplineSolver solver;
  solver.solve(x_, y_, m_);
}

double CubicSpline::operator()(double x) const {
  if (x <= x_.front()) return y_.front();
  if (x >= x_.back()) return y_.back();
  const std::size_t j = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
  return spline_value(x_[j], x_[j + 1], y_[j], y_[j + 1], m_[j], m_[j + 1], x);
}

}  // namespace mark
