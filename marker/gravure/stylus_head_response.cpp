#include "marker/gravure/stylus_head_response.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "base/error.hpp"
#include "driver/sim/stylus_head_model.hpp"
#include "marker/limits/gravure_settings.hpp"

namespace mark {

void validate(const SweepOptions& s) {
  check_range("sweep start frequency", s.start_hz, {10, 45000, "Hz"});
  check_range("sweep stop frequency", s.stop_hz, {10, 45000, "Hz"});
  if (!(s.stop_hz > s.start_hz)) throw InputError("sweep: the stop frequency must lie above the start frequency");
  check_range("sweep tones", s.tones, {8, 1000, ""});
  check_range("sweep amplitude", s.amplitude_um, {0.01, 100, "µm"});
  check_range("sweep offset", s.offset_um, {-200, 200, "µm"});
  check_range("sweep settle time", s.settle_s, {0.001, 1, "s"});
  check_range("sweep measure time", s.measure_s, {0.001, 1, "s"});
}

SweepPattern::SweepPattern(const SweepOptions& options) : options_(options) {
  validate(options_);
  const double ratio = std::pow(options_.stop_hz / options_.start_hz, 1.0 / (options_.tones - 1));
  std::uint64_t start = 0;
  for (int i = 0; i < options_.tones; ++i) {
    const double f = options_.start_hz * std::pow(ratio, i);
    // At least 3 periods measured, so the fit separates the tone from the offset.
    const double measure_s = std::max(options_.measure_s, 3 / f);
    const auto settle = static_cast<std::uint64_t>(std::llround(options_.settle_s * kStylusRate_hz));
    const auto measure = static_cast<std::uint64_t>(std::llround(measure_s * kStylusRate_hz));
    tones_.push_back({f, start, settle, settle + measure});
    start += settle + measure;
  }
  total_ = start;
}

double SweepPattern::duration_s() const { return static_cast<double>(total_) * kStylusTick_s; }

double SweepPattern::value(std::uint64_t n) const {
  const Tone& t = tones_[tone_];
  const double phase = 2 * std::numbers::pi * t.freq_hz * static_cast<double>(n - t.start) * kStylusTick_s;
  return options_.offset_um + options_.amplitude_um * std::sin(phase);
}

std::size_t SweepPattern::next(std::span<double> out) {
  std::size_t k = 0;
  while (k < out.size() && at_ < total_) {
    if (at_ == 0) tone_ = 0;
    while (at_ >= tones_[tone_].start + tones_[tone_].length) ++tone_;
    out[k++] = value(at_++);
  }
  return k;
}

void SweepPattern::check_length(std::span<const float> signal, const char* what) const {
  if (signal.size() < total_)
    throw InputError(std::string("head response: ") + std::to_string(signal.size()) + " sensed " + what +
                     " samples for a pattern of " + std::to_string(total_));
}

SweepPattern::ToneFit SweepPattern::fit_tone(const Tone& t, std::span<const float> sensed) const {
  // Least squares y ≈ c + a·cos(ωn) + b·sin(ωn) over the measured part of the tone.
  const double w = 2 * std::numbers::pi * t.freq_hz * kStylusTick_s;
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d aty = Eigen::Vector3d::Zero();
  for (std::uint64_t n = t.settle; n < t.length; ++n) {
    const Eigen::Vector3d row(1, std::cos(w * n), std::sin(w * n));
    ata += row * row.transpose();
    aty += row * static_cast<double>(sensed[t.start + n]);
  }
  const Eigen::Vector3d p = ata.ldlt().solve(aty);
  // The residual sets the uncertainty: var(a), var(b) = s² · diag((AᵀA)⁻¹).
  double rss = 0;
  for (std::uint64_t n = t.settle; n < t.length; ++n) {
    const double r = sensed[t.start + n] - (p[0] + p[1] * std::cos(w * n) + p[2] * std::sin(w * n));
    rss += r * r;
  }
  const double count = static_cast<double>(t.length - t.settle);
  const Eigen::Matrix3d cov = ata.inverse() * (rss / std::max(1.0, count - 3));
  // y = Re{(a − j b) e^{jωn}}.
  return {{p[1], -p[2]}, std::sqrt(cov(1, 1) + cov(2, 2))};
}

std::vector<ResponsePoint> SweepPattern::measure(std::span<const float> sensed) const {
  check_length(sensed, "position");
  std::vector<ResponsePoint> out;
  // drive = Re{−j A e^{jωn}}.
  const std::complex<double> u(0, -options_.amplitude_um);
  for (const Tone& t : tones_) {
    const ToneFit f = fit_tone(t, sensed);
    out.push_back({t.freq_hz, f.y / u, f.sigma / options_.amplitude_um, 0});
  }
  return out;
}

std::vector<ResponsePoint> SweepPattern::measure_velocity(std::span<const float> sensed) const {
  check_length(sensed, "velocity");
  std::vector<ResponsePoint> out;
  const std::complex<double> u(0, -options_.amplitude_um);
  for (const Tone& t : tones_) {
    const ToneFit f = fit_tone(t, sensed);
    // v = ẋ: the position's complex amplitude is the velocity's over jω (ω in rad/s).
    const double omega = 2 * std::numbers::pi * t.freq_hz;
    out.push_back({t.freq_hz, f.y / (std::complex<double>(0, omega) * u),
                   f.sigma / (omega * options_.amplitude_um), 1});
  }
  return out;
}

std::vector<ResponsePoint> SweepPattern::measure(std::span<const float> sensed_um,
                                                 std::span<const float> sensed_um_s) const {
  return fuse(measure(sensed_um), measure_velocity(sensed_um_s));
}

std::complex<double> point_response(const StylusHeadModel& head, const ResponsePoint& point) {
  const double w = point.velocity_weight;
  std::complex<double> h = 0;
  if (w < 1) h += (1 - w) * held_response(head, point.freq_hz);
  if (w > 0)
    h += w * held_velocity_response(head, point.freq_hz) / std::complex<double>(0, 2 * std::numbers::pi * point.freq_hz);
  return h;
}

std::string_view to_string(ResponseSource source) {
  switch (source) {
    case ResponseSource::position: return "position";
    case ResponseSource::velocity: return "velocity";
    case ResponseSource::fused: break;
  }
  return "both";
}

std::vector<ResponsePoint> fuse(std::span<const ResponsePoint> position, std::span<const ResponsePoint> velocity) {
  if (position.size() != velocity.size())
    throw InputError("response fusion: " + std::to_string(position.size()) + " position tones and " +
                     std::to_string(velocity.size()) + " velocity tones; the two must come from one sweep");
  std::vector<ResponsePoint> out;
  for (std::size_t i = 0; i < position.size(); ++i) {
    const ResponsePoint &p = position[i], &v = velocity[i];
    if (p.freq_hz != v.freq_hz)
      throw InputError("response fusion: tone " + std::to_string(i) + " is at " + std::to_string(p.freq_hz) +
                       " Hz in the position and " + std::to_string(v.freq_hz) + " Hz in the velocity");
    // Weights 1/σ²; as the velocity's share, σp² / (σp² + σv²), which also covers a zero σ.
    const double vp = p.sigma * p.sigma, vv = v.sigma * v.sigma;
    const double share = vp + vv > 0 ? vp / (vp + vv) : 0.5;
    const double sigma = vp + vv > 0 ? std::sqrt(vp * vv / (vp + vv)) : 0.0;
    out.push_back({p.freq_hz, (1 - share) * p.gain + share * v.gain, sigma, share});
  }
  return out;
}

}  // namespace mark
