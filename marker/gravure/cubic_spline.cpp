#include "marker/gravure/cubic_spline.hpp"

#include <algorithm>
#include <limits>
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

StreamingSpline::StreamingSpline(std::size_t window, std::size_t overlap)
    : window_(window ? window : 1), overlap_(overlap) {}

void StreamingSpline::push(double x, double y) {
  if (finished_) throw std::logic_error("spline: knot after finish()");
  if (!x_.empty() && !(x > x_.back())) throw std::invalid_argument("spline: knots must be strictly increasing");
  x_.push_back(x);
  y_.push_back(y);
  m_.push_back(0);
  if (x_.size() >= committed_ + window_ + overlap_ + 1) solve_window(false);
}

void StreamingSpline::finish() {
  if (finished_) return;
  finished_ = true;
  if (committed_ < x_.size()) solve_window(true);
}

// Solves from the last committed knot (its M fixed; M = 0 at the very start) to the end of the
// look-ahead (M = 0 there: the natural end, artificial unless it is the real end) and commits
// the window.
void StreamingSpline::solve_window(bool to_end) {
  const std::size_t left = committed_ == 0 ? 0 : committed_ - 1;
  const std::size_t right = to_end ? x_.size() - 1 : committed_ + window_ + overlap_;
  if (committed_ == 0) m_[0] = 0;
  scratch_m_.assign(right - left + 1, 0.0);
  scratch_m_.front() = m_[left];
  scratch_m_.back() = 0;
  const std::span<const double> xs(x_.data() + left, right - left + 1), ys(y_.data() + left, right - left + 1);
  solver_.solve(xs, ys, scratch_m_);
  const std::size_t end = to_end ? x_.size() : committed_ + window_;
  for (std::size_t i = std::max<std::size_t>(left, 1); i < end; ++i) m_[i] = scratch_m_[i - left];
  if (to_end) m_.back() = 0;
  committed_ = end;
}

double StreamingSpline::committed_x() const {
  if (committed_ == 0) return -std::numeric_limits<double>::infinity();
  if (finished_ && committed_ == x_.size()) return std::numeric_limits<double>::infinity();
  return x_[committed_ - 1];
}

StreamingSpline::Segment StreamingSpline::segment_at(double x) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  // Constant pieces keep a finite x0: t·0 must stay 0.
  if (x_.empty()) return {0, inf, 0, 0, 0, 0};
  if (finished_ && x >= x_.back()) return {x_.back(), inf, y_.back(), 0, 0, 0};
  if (x > committed_x()) throw std::logic_error("spline: evaluated beyond the committed knots");
  while (x > x_[segment_ + 1]) ++segment_;  // stops at the last committed knot at the latest
  if (segment_ > 8192) compact();
  const std::size_t j = segment_;
  if (x < x_[j]) return {x_[j], x_[j], y_[j], 0, 0, 0};
  const double h = x_[j + 1] - x_[j], m0 = m_[j], m1 = m_[j + 1];
  return {x_[j], x_[j + 1], y_[j], (y_[j + 1] - y_[j]) / h - h * (2 * m0 + m1) / 6, m0 / 2, (m1 - m0) / (6 * h)};
}

// Drops the knots behind the evaluation cursor so memory stays bounded on a long stream.
void StreamingSpline::compact() {
  const std::size_t drop = segment_;
  x_.erase(x_.begin(), x_.begin() + static_cast<std::ptrdiff_t>(drop));
  y_.erase(y_.begin(), y_.begin() + static_cast<std::ptrdiff_t>(drop));
  m_.erase(m_.begin(), m_.begin() + static_cast<std::ptrdiff_t>(drop));
  base_ += drop;
  committed_ -= drop;
  segment_ = 0;
}

}  // namespace mark
