#include "driver/sim/head_response.hpp"

#include <cmath>
#include <numbers>

namespace mark {
namespace {

// Holds long enough for the slowest plausible head (τ up to ~0.6 ms, intelliSCAN 30) to settle
// to far below a micrometre after a small part, and to finish a large jump.
constexpr double kSettle_s = 4e-3;
constexpr double kJumpSettle_s = 12e-3;

class PatternWriter {
 public:
  explicit PatternWriter(ResponsePattern& p) : p_(p) {}

  void hold(double seconds) {
    const auto n = static_cast<std::size_t>(std::lround(seconds / p_.tick_s));
    for (std::size_t i = 0; i < n; ++i) emit(at_);
  }
  void step(Vec2 to) {
    at_ = to;
    emit(at_);
  }
  void ramp(Vec2 to, double speed_mm_s) {
    const Vec2 from = at_;
    const double len = norm(to - from);
    const auto n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(len / (speed_mm_s * p_.tick_s))));
    for (std::size_t i = 1; i <= n; ++i) emit(from + (static_cast<double>(i) / n) * (to - from));
    at_ = to;
  }
  // x = x0 + A·sin(φ(t)), φ' = 2π·f(t), f linear from f0 to f1 over `seconds`; ends back at x0
  // (the last partial period is faded out over its last millisecond).
  void chirp(double amplitude, double f0_hz, double f1_hz, double seconds) {
    const Vec2 x0 = at_;
    const auto n = static_cast<std::size_t>(std::lround(seconds / p_.tick_s));
    const double fade = 1e-3;
    for (std::size_t i = 1; i <= n; ++i) {
      const double t = static_cast<double>(i) * p_.tick_s;
      const double phase = 2 * std::numbers::pi * (f0_hz * t + (f1_hz - f0_hz) * t * t / (2 * seconds));
      const double w = std::min(1.0, std::min(t, seconds - t) / fade);
      emit(x0 + Vec2{amplitude * w * std::sin(phase), 0});
    }
    at_ = x0;
  }

  void begin(ResponsePartKind kind, int axis, double size) {
    p_.parts.push_back({kind, axis, p_.commands.size(), 0, size});
  }
  void end() { p_.parts.back().count = p_.commands.size() - p_.parts.back().first; }
  Vec2 at() const { return at_; }

 private:
  void emit(Vec2 p) {
    p_.commands.push_back({static_cast<float>(p.x), static_cast<float>(p.y), false, 255});
  }
  ResponsePattern& p_;
  Vec2 at_{0, 0};
};

}  // namespace

ResponsePattern head_response_pattern(double field_mm, double tick_s) {
  ResponsePattern p;
  p.tick_s = tick_s;
  PatternWriter w(p);
  w.hold(kSettle_s);
  for (double s : {0.002, 0.005, 0.010}) {
    for (double sign : {1.0, -1.0}) {
      w.begin(ResponsePartKind::small_step, 0, s);
      w.step({sign * s, 0});
      w.hold(kSettle_s);
      w.step({0, 0});
      w.hold(kSettle_s);
      w.end();
    }
  }
  for (double v : {20.0, 50.0, 100.0}) {
    const double len = v * 2e-3;
    w.begin(ResponsePartKind::ramp, 0, len);
    w.ramp({len, 0}, v);
    w.hold(kSettle_s);
    w.ramp({0, 0}, v);
    w.hold(kSettle_s);
    w.end();
  }
  w.begin(ResponsePartKind::chirp, 0, 0.005);
  w.chirp(0.005, 100, 3000, 30e-3);
  w.hold(kSettle_s);
  w.end();
  for (int axis : {0, 1}) {
    for (double share : {0.02, 0.10, 0.45}) {
      const double half = share * field_mm / 2;
      Vec2 a{0, 0}, b{0, 0};
      (axis == 0 ? a.x : a.y) = -half;
      (axis == 0 ? b.x : b.y) = half;
      w.step(a);  // positioning move, not measured
      w.hold(kJumpSettle_s);
      w.begin(ResponsePartKind::large_step, axis, 2 * half);
      w.step(b);
      w.hold(kJumpSettle_s);
      w.step(a);
      w.hold(kJumpSettle_s);
      w.end();
    }
    w.step({0, 0});
    w.hold(kJumpSettle_s);
  }
  return p;
}

ResponseRecord measure_head_response(const SimScannerOptions& head_options,
                                     const ResponsePattern& pattern) {
  SimScannerOptions o = head_options;
  o.tick_s = pattern.tick_s;
  o.record_lit_paths = false;
  o.probe = nullptr;
  SimScanner head(o);
  ResponseRecord r;
  r.pattern = pattern;
  r.position.reserve(pattern.commands.size());
  for (const ScanSample& s : pattern.commands) {
    head.write(std::span<const ScanSample>(&s, 1));
    r.position.push_back(head.beam());
  }
  return r;
}

}  // namespace mark
