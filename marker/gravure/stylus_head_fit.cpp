#include "marker/gravure/stylus_head_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "base/error.hpp"

namespace mark {
namespace {

constexpr double kRelativeFloor = 0.01;
constexpr double kReliableSnr = 10;  // |H| / σ for a point to count in peak search and error

struct Peak {
  double freq_hz;
  double prominence_db;
};

// Local maxima of |H| (dB) whose prominence — height above the lowest point between them and
// the next higher point (or the end) on each side — is at least min_db.
std::vector<Peak> find_peaks(std::span<const ResponsePoint> r, double min_db) {
  std::vector<double> db(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) db[i] = 20 * std::log10(std::abs(r[i].gain));
  std::vector<Peak> peaks;
  for (std::size_t i = 1; i + 1 < r.size(); ++i) {
    if (!(db[i] > db[i - 1] && db[i] >= db[i + 1])) continue;
    double left = db[i], right = db[i];
    for (std::size_t j = i; j-- > 0 && db[j] <= db[i];) left = std::min(left, db[j]);
    for (std::size_t j = i + 1; j < r.size() && db[j] <= db[i]; ++j) right = std::min(right, db[j]);
    const double prominence = db[i] - std::max(left, right);
    if (prominence < min_db) continue;
    // Parabola through the three points in (log f, dB) for the peak's frequency.
    const double x0 = std::log(r[i - 1].freq_hz), x1 = std::log(r[i].freq_hz), x2 = std::log(r[i + 1].freq_hz);
    const double d1 = (db[i] - db[i - 1]) / (x1 - x0), d2 = (db[i + 1] - db[i]) / (x2 - x1);
    const double curvature = (d2 - d1) / ((x2 - x0) / 2);
    double x = x1;
    if (curvature < 0) x = std::clamp((x0 + x1) / 2 - d1 / curvature, x0, x2);
    peaks.push_back({std::exp(x), prominence});
  }
  std::sort(peaks.begin(), peaks.end(), [](auto a, auto b) { return a.prominence_db > b.prominence_db; });
  return peaks;
}

// Residuals of the held modal model for θ = (ln f_i, ln ζ_i), gains by linear least squares.
struct ResponseFunctor {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  std::span<const ResponsePoint> points;
  int modes;
  mutable int evaluations = 0;

  int inputs() const { return 2 * modes; }
  int values() const { return static_cast<int>(2 * points.size()); }

  // The model for θ, with its gains; returns the weighted residual vector in `res`.
  StylusHeadModel model(const Eigen::VectorXd& theta, Eigen::VectorXd* res) const {
    const Eigen::Index k = static_cast<Eigen::Index>(points.size());
    StylusHeadModel m;
    for (int i = 0; i < modes; ++i)
      m.modes.push_back({std::exp(theta[2 * i]), std::min(0.999, std::exp(theta[2 * i + 1])), 1.0});
    Eigen::MatrixXd a(2 * k, modes);
    Eigen::VectorXd b(2 * k);
    for (Eigen::Index p = 0; p < k; ++p) {
      const std::complex<double> h = points[p].gain;
      // Weighted by the point's uncertainty: its measurement noise, or 1 % of |H| where the
      // noise is smaller, so a well-measured small gain counts as much as a peak.
      const double w = 1 / std::hypot(kRelativeFloor * std::abs(h), points[p].sigma);
      for (int i = 0; i < modes; ++i) {
        const std::complex<double> hi = point_response({{m.modes[i]}}, points[p]);
        a(2 * p, i) = hi.real() * w;
        a(2 * p + 1, i) = hi.imag() * w;
      }
      b[2 * p] = h.real() * w;
      b[2 * p + 1] = h.imag() * w;
    }
    const Eigen::VectorXd g = a.colPivHouseholderQr().solve(b);
    for (int i = 0; i < modes; ++i) m.modes[i].gain = g[i];
    if (res) *res = a * g - b;
    return m;
  }

  int operator()(const Eigen::VectorXd& theta, Eigen::VectorXd& res) const {
    ++evaluations;
    model(theta, &res);
    return 0;
  }
};

}  // namespace

namespace {

// Fits n modes started at the n most prominent peaks; the model with its residual.
HeadFit fit_modes(std::span<const ResponsePoint> response, std::vector<Peak> peaks, int n) {
  peaks.resize(static_cast<std::size_t>(n));
  std::sort(peaks.begin(), peaks.end(), [](auto a, auto b) { return a.freq_hz < b.freq_hz; });
  ResponseFunctor f{response, n};
  Eigen::VectorXd theta(2 * n);
  for (int i = 0; i < n; ++i) {
    theta[2 * i] = std::log(peaks[i].freq_hz);
    theta[2 * i + 1] = std::log(0.05);
  }
  Eigen::NumericalDiff<ResponseFunctor> diff(f);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<ResponseFunctor>> lm(diff);
  lm.parameters.maxfev = 4000;
  lm.parameters.xtol = 1e-12;
  lm.parameters.ftol = 1e-12;
  lm.minimize(theta);
  HeadFit fit;
  fit.model = f.model(theta, nullptr);
  fit.evaluations = diff.evaluations;
  std::sort(fit.model.modes.begin(), fit.model.modes.end(), [](auto a, auto b) { return a.freq_hz < b.freq_hz; });
  // The error over the points measured well enough to judge it.
  double sum = 0;
  int count = 0;
  for (const ResponsePoint& p : response) {
    if (std::abs(p.gain) < kReliableSnr * p.sigma) continue;
    sum += std::norm((point_response(fit.model, p) - p.gain) / std::abs(p.gain));
    ++count;
  }
  fit.rms_relative_error = count ? std::sqrt(sum / count) : 0;
  return fit;
}

bool physical(const StylusHeadModel& m) {
  for (const StylusMode& mode : m.modes)
    if (!(mode.gain > 0) || !(mode.damping > 0 && mode.damping < 0.999)) return false;
  return true;
}

}  // namespace

HeadFit fit_head(std::span<const ResponsePoint> response, int modes) {
  if (response.size() < 8) throw InputError("head fit: at least 8 response points are needed");
  for (const ResponsePoint& p : response)
    if (!(std::abs(p.gain) > 0) || !std::isfinite(std::abs(p.gain)))
      throw InputError("head fit: the response at " + std::to_string(p.freq_hz) + " Hz is zero or not finite");
  // Peaks only where the measurement stands clear of its noise.
  std::vector<ResponsePoint> reliable;
  for (const ResponsePoint& p : response)
    if (std::abs(p.gain) >= kReliableSnr * p.sigma) reliable.push_back(p);
  std::vector<Peak> peaks = find_peaks(reliable, 3.0);
  if (peaks.empty()) throw InputError("head fit: the measured response has no resonance peak (3 dB or more)");
  if (modes > static_cast<int>(peaks.size()))
    throw InputError("head fit: " + std::to_string(modes) + " resonances asked for, " + std::to_string(peaks.size()) +
                     " found in the response");
  // As many modes as peaks (at most 4); a fit that ends non-physical — a peak that was noise —
  // is retried without the least prominent peak.
  const int most = modes > 0 ? modes : static_cast<int>(std::min<std::size_t>(peaks.size(), 4));
  const int least = modes > 0 ? modes : 1;
  HeadFit fit;
  for (int n = most; n >= least; --n) {
    fit = fit_modes(response, peaks, n);
    if (physical(fit.model)) return fit;
  }
  const StylusMode& bad = *std::find_if(fit.model.modes.begin(), fit.model.modes.end(),
                                        [](const StylusMode& m) { return !physical({{m}}); });
  throw InputError("head fit: the fit ended on a resonance at " + std::to_string(bad.freq_hz) + " Hz with gain " +
                   std::to_string(bad.gain) + " and damping " + std::to_string(bad.damping) +
                   ", not a physical head; the response may be too noisy");
}

}  // namespace mark
