// The tuning filters: the seed's C1/C2 against the numbers in dynamics.md §6.2 and against the
// RBJ cookbook's notch, every section's measured response (an impulse through the transposed
// direct form II biquads, then its DFT) against the designed one within 0.1 dB, unity DC gain,
// notch depth, and the start without a ring.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "base/error.hpp"
#include "marker/gravure/biquad_cascade.hpp"
#include "marker/gravure/head_design.hpp"
#include "marker/gravure/tuning_filter.hpp"

namespace mark {
namespace {

constexpr double kFs = 200000;

// The response measured from the impulse response: its DFT at f.
std::complex<double> measured(const std::vector<double>& impulse, double f) {
  std::complex<double> sum = 0;
  const double w = 2 * std::numbers::pi * f / kFs;
  for (std::size_t n = 0; n < impulse.size(); ++n) sum += impulse[n] * std::polar(1.0, -w * static_cast<double>(n));
  return sum;
}

std::vector<double> impulse_response(const FilterBank& bank, std::size_t length) {
  BiquadCascade cascade(bank);
  std::vector<double> h(length, 0.0);
  h[0] = 1;
  cascade.process(h);
  return h;
}

double db(std::complex<double> h) { return 20 * std::log10(std::abs(h)); }

TEST(MatchedZ, ReproducesThePatentCoefficientsOfDynamicsMd) {
  struct Row {
    double f, d, c1, c2;
  };
  // ../shared/reference/dynamics.md §6.2, Fs = 200 kHz.
  const Row rows[] = {{3200, 0.05, 1.979950, 0.989997}, {3200, 0.20, 1.950688, 0.960585},
                      {4000, 0.05, 1.971840, 0.987512}, {4000, 0.50, 1.867091, 0.881911},
                      {8000, 0.05, 1.913130, 0.975180}, {8000, 0.50, 1.722208, 0.777768}};
  for (const Row& r : rows) {
    const MatchedZ m = matched_z(r.f, r.d);
    EXPECT_NEAR(m.c1, r.c1, 5e-7) << r.f << " Hz, d " << r.d;
    EXPECT_NEAR(m.c2, r.c2, 5e-7) << r.f << " Hz, d " << r.d;
    // The formula written out exactly as the patent prints it.
    const double T = 0.000005, pi = std::numbers::pi;
    EXPECT_DOUBLE_EQ(m.c1, 2 * std::cos(T * 2 * pi * r.f * std::sqrt(1 - r.d * r.d)) * std::exp(-T * 2 * pi * r.f * r.d));
    EXPECT_DOUBLE_EQ(m.c2, std::pow(std::exp(-T * 2 * pi * r.f * r.d), 2));
  }
}

TEST(MatchedZ, AgreesWithTheRbjCookbookPolesBelowAQuarterOfTheClock) {
  // RBJ notch (bilinear with pre-warping), Q = 1/(2d): a0 = 1 + α, a1 = −2 cos w0, a2 = 1 − α.
  const double rbj[][4] = {{3200, 0.05, 1.979966, 0.990014}, {3200, 0.20, 1.950746, 0.960645},
                           {4000, 0.05, 1.971872, 0.987545}, {4000, 0.50, 1.867217, 0.882058},
                           {8000, 0.05, 1.913374, 0.975436}, {8000, 0.50, 1.722929, 0.778814}};
  for (const auto& r : rbj) {
    const double w0 = 2 * std::numbers::pi * r[0] / kFs, alpha = std::sin(w0) * r[1];  // sin/(2Q), Q = 1/(2d)
    const double a0 = 1 + alpha, a1 = -2 * std::cos(w0), a2 = 1 - alpha;
    EXPECT_NEAR(-a1 / a0, r[2], 5e-7);
    EXPECT_NEAR(a2 / a0, r[3], 5e-7);
    const MatchedZ m = matched_z(r[0], r[1]);
    // Same pole pair to within 0.1 % in radius (the designs differ in their zeros: RBJ puts them
    // on the unit circle, the patent's pair at the resonance's own radius).
    EXPECT_NEAR(std::sqrt(m.c2) / std::sqrt(a2 / a0), 1, 1e-3) << r[0] << " Hz";
    EXPECT_NEAR(m.c1 / (-a1 / a0), 1, 1e-3);
  }
}

TEST(MatchedZ, ContinuesThroughCriticalDamping) {
  // d ≥ 1: the two real poles e^{s1 T}, e^{s2 T}.
  const double f = 3000, d = 1.5, w = 2 * std::numbers::pi * f, T = 5e-6;
  const double s1 = -d * w + w * std::sqrt(d * d - 1), s2 = -d * w - w * std::sqrt(d * d - 1);
  const MatchedZ m = matched_z(f, d);
  EXPECT_NEAR(m.c1, std::exp(s1 * T) + std::exp(s2 * T), 1e-12);
  EXPECT_NEAR(m.c2, std::exp((s1 + s2) * T), 1e-12);
  const MatchedZ below = matched_z(f, 1 - 1e-9), above = matched_z(f, 1 + 1e-9);
  EXPECT_NEAR(below.c1, above.c1, 1e-7);
}

TEST(TuningFilter, ImpulseResponseMatchesTheDesignWithinATenthOfADecibel) {
  const std::vector<FilterBank> banks{
      {{notch_section(1800, 0.06, 18)}, 1},
      {{notch_section(5500, 0.04, 22)}, 1},
      {{emphasis_section(5500, 0.5, 20000, 0.7071)}, 1},
      {{{SectionKind::antiresonance, 1800, 0.5, 3368, 0.042}}, 1},
      design_for_head(default_stylus_head())};
  for (std::size_t b = 0; b < banks.size(); ++b) {
    // The slowest pole (the antiresonance, radius 0.9956) decays to < 1e-60 in 2^15 samples.
    const std::vector<double> h = impulse_response(banks[b], 1 << 15);
    for (double f = 50; f < 40000; f *= 1.17) {
      const double design = db(response(banks[b], f)), got = db(measured(h, f));
      EXPECT_NEAR(got, design, 0.1) << "bank " << b << " at " << f << " Hz";
      EXPECT_NEAR(got, design, 1e-6) << "bank " << b << " at " << f << " Hz";  // in fact exactly
    }
  }
}

TEST(TuningFilter, UnityGainAtDcAndTheNotchDepth) {
  for (double depth : {6.0, 12.0, 20.0}) {
    const FilterSection s = notch_section(2000, 0.05, depth);
    EXPECT_NEAR(std::abs(response(design(s), 0)), 1, 1e-12);
    // At the notch the gain is close to d_z/d_p = −depth dB (exact for an analogue notch; the
    // matched-z pair differs by a few tenths of a dB at this frequency).
    EXPECT_NEAR(db(response(design(s), 2000)), -depth, 0.3) << depth;
    // and it is the deepest point around.
    EXPECT_LT(db(response(design(s), 2000)), db(response(design(s), 1800)));
    EXPECT_LT(db(response(design(s), 2000)), db(response(design(s), 2200)));
  }
}

TEST(TuningFilter, EmphasisRisesAboveItsFrequency) {
  const FilterSection e = emphasis_section(2000, 0.7, 10000, 0.7);
  EXPECT_NEAR(db(response(design(e), 100)), 0, 0.05);
  // Far above both corners the gain approaches (f_p / f_z)² = 25 (28 dB).
  EXPECT_NEAR(db(response(design(e), 40000)), 28, 1.5);
  EXPECT_GT(db(response(design(e), 5000)), 6);
}

TEST(BiquadCascade, SettledStartDoesNotRing) {
  BiquadCascade c(design_for_head(default_stylus_head()));
  c.settle(-5);
  std::vector<double> x(2000, -5.0);
  c.process(x);
  for (double v : x) EXPECT_NEAR(v, -5 * (1 / default_stylus_head().static_gain()), 1e-9);
}

TEST(BiquadCascade, RefusesImpossibleSections) {
  EXPECT_THROW(BiquadCascade({{notch_section(60000, 0.05, 10)}, 1}), InputError);
  EXPECT_THROW(BiquadCascade({{{SectionKind::notch, 1000, 0.05, 1000, 0}}, 1}), InputError);
  try {
    BiquadCascade({{notch_section(1800, 0.06, 10), {SectionKind::emphasis, 5000, -1, 9000, 0.7}}, 1});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "filter section 2 (emphasis) zero damping: -1 is outside the range 0 to 10");
  }
}

}  // namespace
}  // namespace mark
