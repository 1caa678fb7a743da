// Arc length of an ellipse by adaptive Gauss–Legendre quadrature. The integrand |d/dθ| is smooth
// and periodic, so a 10-point rule on a few subintervals reaches 1e-12 relative quickly.
#include <array>
#include <cmath>
#include <limits>

#include "fonts/element.hpp"

namespace mark {
namespace {

constexpr std::array<double, 5> kNodes = {0.1488743389816312, 0.4333953941292472,
                                          0.6794095682990244, 0.8650633666889845,
                                          0.9739065285171717};
constexpr std::array<double, 5> kWeights = {0.2955242247147529, 0.2692667193099963,
                                            0.2190863625159820, 0.1494513491505806,
                                            0.0666713443086881};

// |d/dθ| of the ellipse point. A plain square root: std::hypot's overflow guard costs several
// times as much and the operands here are millimetres.
double speed(double rx, double ry, double th) {
  const double a = rx * std::sin(th), b = ry * std::cos(th);
  return std::sqrt(a * a + b * b);
}

double gauss10(double rx, double ry, double a, double b) {
  const double m = (a + b) / 2, h = (b - a) / 2;
  double sum = 0;
  for (std::size_t i = 0; i < kNodes.size(); ++i)
    sum += kWeights[i] * (speed(rx, ry, m - h * kNodes[i]) + speed(rx, ry, m + h * kNodes[i]));
  return sum * h;
}

double adaptive(double rx, double ry, double a, double b, double whole, double tol, int depth) {
  const double m = (a + b) / 2;
  const double left = gauss10(rx, ry, a, m), right = gauss10(rx, ry, m, b);
  // Quarter-turn pieces converge in a few levels. The halved tolerance must not sink below the
  // sum's own rounding; the depth cap bounds anything else (2^20 pieces), and a sum that is not
  // finite ends at once (it never compares below a tolerance).
  const double noise = 64 * std::numeric_limits<double>::epsilon() * std::abs(left + right);
  if (depth >= 20 || !std::isfinite(left + right) || std::abs(left + right - whole) <= std::max(tol, noise))
    return left + right;
  return adaptive(rx, ry, a, m, left, tol / 2, depth + 1) +
         adaptive(rx, ry, m, b, right, tol / 2, depth + 1);
}

}  // namespace

double ellipse_arc_length(double rx, double ry, double theta0, double theta1) {
  if (theta1 < theta0) std::swap(theta0, theta1);
  if (theta1 == theta0) return 0.0;
  if (!std::isfinite(rx) || !std::isfinite(ry) || !std::isfinite(theta0) || !std::isfinite(theta1))
    return std::numeric_limits<double>::quiet_NaN();
  // Radii near 1e160 overflow the squares in speed(): integrate the ellipse scaled to a unit
  // major semi-axis (fuzz_glyph_script found a radius of 2e169 splitting every piece 2^20 times).
  if (const double scale = std::max(std::abs(rx), std::abs(ry)); scale > 1e100)
    return scale * ellipse_arc_length(rx / scale, ry / scale, theta0, theta1);
  // The speed is periodic in θ: whole turns are multiples of the perimeter, and the start is
  // taken modulo a turn, so a sweep of many turns or a start at 1e20 rad (where adding a quarter
  // turn no longer changes θ) cannot loop for ever.
  const double turn = 2 * std::acos(-1.0);
  const double sweep = theta1 - theta0;
  if (std::abs(theta0) > turn) theta0 = std::fmod(theta0, turn);
  if (sweep > turn) {
    const double turns = std::floor(sweep / turn);
    return turns * ellipse_arc_length(rx, ry, 0, turn) +
           ellipse_arc_length(rx, ry, theta0, theta0 + std::min(turn, sweep - turns * turn));
  }
  theta1 = theta0 + sweep;
  // Quarter-turn pieces keep each subinterval free of the integrand's kinks in high eccentricity.
  const double rough = (theta1 - theta0) * std::max(rx, ry);
  const double tol = 1e-13 * rough;
  double total = 0;
  const double step = std::acos(-1.0) / 2;
  for (double a = theta0; a < theta1; a += step) {
    const double b = std::min(theta1, a + step);
    total += adaptive(rx, ry, a, b, gauss10(rx, ry, a, b), tol, 0);
  }
  return total;
}

}  // namespace mark
