#pragma once
// The exact discretisation of a linear second-order loop over one sub-step, for the simulated
// head's servo (ωn, ζ) and its mirror resonance: ẍ = ωn²·(c − x) − 2ζωn·ẋ with the target c
// moving at a constant rate ċ over the step (the command is linear within a tick). About the
// loop's steady ramp (x = c − (2ζ/ωn)·ċ, ẋ = ċ) the error obeys the free loop, so the state after
// dt is the transition matrix e^{A·dt} times the error before — exact for every ζ and ωn·dt, so
// stable wherever the continuous loop is (an explicit step of the same loop diverges once
// 2ζωn·dt > 2: ζ ≈ 7.75 on SL10 at 1 µs).
namespace mark {

struct SecondOrderStep {
  double yy = 1, yv = 0;  // error    ← yy·error + yv·ė
  double vy = 0, vv = 1;  // ė        ← vy·error + vv·ė
  double lag = 0;         // 2ζ/ωn: the steady ramp's lag
  double dt = 0;

  // Advances (x, v) by one step towards the target c at the step's start, moving at `rate`.
  void apply(double& x, double& v, double c, double rate = 0) const {
    const double y = x - (c - lag * rate), u = v - rate;
    x = c + rate * (dt - lag) + yy * y + yv * u;
    v = rate + vy * y + vv * u;
  }
};

// e^{A·dt} for A = [[0, 1], [−ωn², −2ζωn]]; ωn > 0, ζ ≥ 0, dt > 0.
SecondOrderStep second_order_step(double omega_n, double zeta, double dt);

}  // namespace mark
