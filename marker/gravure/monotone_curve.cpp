#include "marker/gravure/monotone_curve.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mark {

double monotone_slope(double h0, double d0, double h1, double d1) {
  if (d0 * d1 <= 0) return 0;
  // Fritsch–Butland: weights favour the shorter interval; |slope| ≤ 3·min(|d0|, |d1|), inside
  // the Fritsch–Carlson region where each piece stays monotone.
  const double w0 = 2 * h1 + h0, w1 = h1 + 2 * h0;
  return (w0 + w1) / (w0 / d0 + w1 / d1);
}

void MonotoneCurve::push(double x, double y) {
  if (finished_) throw std::logic_error("monotone curve: knot after finish()");
  if (!std::isfinite(x) || !std::isfinite(y)) throw std::invalid_argument("monotone curve: knots must be finite");
  if (!x_.empty() && !(x > x_.back())) throw std::invalid_argument("monotone curve: knots must be strictly increasing");
  x_.push_back(x);
  y_.push_back(y);
}

void MonotoneCurve::finish() { finished_ = true; }

// Slope at knot i is known once knot i+1 is in (or the stream has ended).
bool MonotoneCurve::slope_known(std::size_t i) const { return i + 1 < x_.size() || (finished_ && i < x_.size()); }

double MonotoneCurve::slope(std::size_t i) const {
  // The ends (the stylus lifted before the first cell and after the last) are flat.
  if (i + 1 >= x_.size() || (i == 0 && base_ == 0)) return 0;
  if (i == 0) throw std::logic_error("monotone curve: slope of a dropped knot's neighbour");
  const double h0 = x_[i] - x_[i - 1], h1 = x_[i + 1] - x_[i];
  return monotone_slope(h0, (y_[i] - y_[i - 1]) / h0, h1, (y_[i + 1] - y_[i]) / h1);
}

double MonotoneCurve::committed_x() const {
  if (finished_) return std::numeric_limits<double>::infinity();
  // Knot i's piece [x_i, x_{i+1}] needs slopes at i and i+1: knots up to i+2.
  if (x_.size() < 3) return -std::numeric_limits<double>::infinity();
  return x_[x_.size() - 2];
}

MonotoneCurve::Segment MonotoneCurve::segment_at(double x) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (x_.empty()) return {0, inf, 0, 0, 0, 0};
  if (finished_ && x >= x_.back()) return {x_.back(), inf, y_.back(), 0, 0, 0};
  if (x > committed_x()) throw std::logic_error("monotone curve: evaluated beyond the committed knots");
  while (x > x_[segment_ + 1]) ++segment_;
  if (segment_ > 8192) compact();
  const std::size_t j = segment_;
  if (x < x_[j]) return {x_[j], x_[j], y_[j], 0, 0, 0};
  if (!slope_known(j + 1)) throw std::logic_error("monotone curve: piece not committed");
  // Cubic Hermite on [x_j, x_{j+1}] with end slopes s0, s1.
  const double h = x_[j + 1] - x_[j], d = (y_[j + 1] - y_[j]) / h;
  const double s0 = slope(j), s1 = slope(j + 1);
  return {x_[j], x_[j + 1], y_[j], s0, (3 * d - 2 * s0 - s1) / h, (s0 + s1 - 2 * d) / (h * h)};
}

// Drops the knots behind the evaluation cursor (keeping one before it: its slope needs it).
void MonotoneCurve::compact() {
  const std::size_t drop = segment_ - 1;
  x_.erase(x_.begin(), x_.begin() + static_cast<std::ptrdiff_t>(drop));
  y_.erase(y_.begin(), y_.begin() + static_cast<std::ptrdiff_t>(drop));
  base_ += drop;
  segment_ -= drop;
}

}  // namespace mark
