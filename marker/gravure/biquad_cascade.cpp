#include "marker/gravure/biquad_cascade.hpp"

namespace mark {

BiquadCascade::BiquadCascade(const FilterBank& bank, double tick_s) : gain_(bank.gain) {
  for (std::size_t i = 0; i < bank.sections.size(); ++i) {
    validate(bank.sections[i], i);
    coefficients_.push_back(design(bank.sections[i], tick_s));
  }
  state_.assign(2 * coefficients_.size(), 0.0);
}

namespace {

// N sections, sample by sample, with the state in local variables: the compiler unrolls the
// section loop and keeps the state in registers, and the out-of-order core overlaps section k
// of one sample with section k−1 of the next. (Through memory every state update would wait on
// a store-to-load round trip: several times slower.)
template <std::size_t N>
void run_fixed(const BiquadCoefficients* c, double* state, double gain, std::span<double> samples) {
  double s1[N], s2[N];
  BiquadCoefficients k[N];
  for (std::size_t i = 0; i < N; ++i) {
    s1[i] = state[2 * i];
    s2[i] = state[2 * i + 1];
    k[i] = c[i];
  }
  for (double& v : samples) {
    double x = v;
    for (std::size_t i = 0; i < N; ++i) {
      const double y = k[i].b0 * x + s1[i];
      s1[i] = k[i].b1 * x - k[i].a1 * y + s2[i];
      s2[i] = k[i].b2 * x - k[i].a2 * y;
      x = y;
    }
    v = gain * x;
  }
  for (std::size_t i = 0; i < N; ++i) {
    state[2 * i] = s1[i];
    state[2 * i + 1] = s2[i];
  }
}

// Any number of sections: one section over the whole block at a time.
void run_any(const BiquadCoefficients* c, double* state, std::size_t n, double gain, std::span<double> samples) {
  for (std::size_t i = 0; i < n; ++i) {
    const BiquadCoefficients k = c[i];
    double s1 = state[2 * i], s2 = state[2 * i + 1];
    for (double& v : samples) {
      const double y = k.b0 * v + s1;
      s1 = k.b1 * v - k.a1 * y + s2;
      s2 = k.b2 * v - k.a2 * y;
      v = y;
    }
    state[2 * i] = s1;
    state[2 * i + 1] = s2;
  }
  for (double& v : samples) v *= gain;
}

}  // namespace

void BiquadCascade::process(std::span<double> samples) {
  double* st = state_.data();
  const BiquadCoefficients* c = coefficients_.data();
  switch (coefficients_.size()) {
    case 0: for (double& v : samples) v *= gain_; break;
    case 1: run_fixed<1>(c, st, gain_, samples); break;
    case 2: run_fixed<2>(c, st, gain_, samples); break;
    case 3: run_fixed<3>(c, st, gain_, samples); break;
    case 4: run_fixed<4>(c, st, gain_, samples); break;
    case 5: run_fixed<5>(c, st, gain_, samples); break;
    case 6: run_fixed<6>(c, st, gain_, samples); break;
    default: run_any(c, st, coefficients_.size(), gain_, samples); break;
  }
}

void BiquadCascade::settle(double x) {
  // Every section has unity DC gain, so each sees x in and puts x out; solve the state
  // equations for y = x.
  for (std::size_t k = 0; k < coefficients_.size(); ++k) {
    const BiquadCoefficients& c = coefficients_[k];
    state_[2 * k + 1] = c.b2 * x - c.a2 * x;
    state_[2 * k] = c.b1 * x - c.a1 * x + state_[2 * k + 1];
  }
}

}  // namespace mark
