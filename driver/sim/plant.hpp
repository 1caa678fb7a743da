#pragma once
// The simulated head as it is, apart from the planner's model of it: the effects a real galvo has
// that the head preset (HeadModel, which the planner's profile describes) leaves out. Every
// field's default is "as the model says", so a default Plant is the preset itself, figure for
// figure. The simulated scanner applies it (sim_scanner.cpp); nothing upstream reads it, so the
// planner keeps its own model while the beam follows this one (`--plant`, docs/speed.md).
#include <cstdint>

namespace mark {

struct Plant {
  // The servo's ramp lag τ × this (second order: ωn ÷ this, ζ as is).
  double tau_scale = 1;
  // Second order only: ωn × this at the same ramp lag (so ζ × this too); a first-order servo has
  // no ωn and ignores it.
  double wn_scale = 1;
  // Servo dead time, inside the loop: the servo acts on the shaft's position and speed as they
  // were this long ago (sensor and computation latency), so its ramp lag becomes τ − dead on a
  // first-order loop and its transients ring. Rounded to the sub-step (1 µs at the default tick).
  double dead_us = 0;
  // Command latency, outside the loop: the servo sees every command this much later (the whole
  // response shifted in time). Rounded to the sub-step. The laser is delayed by neither.
  double latency_us = 0;
  // Mirror resonance (the mirror twisting against the motor shaft, which the servo measures):
  // mirror − shaft = r, r̈ + 2ζr·ωr·ṙ + ωr²·r = −(shaft acceleration); zero lag on a ramp, it
  // rings wherever the servo accelerates. 0 Hz: none.
  double resonance_hz = 0;
  double resonance_zeta = 0.02;
  // The mirror's acceleration limit, mm/s² (0: the preset's).
  double accel_max_mm_s2 = 0;
  // Back-EMF, mm/s (0: none): the speed at which the turning coil's back-EMF uses up the
  // amplifier's voltage. Speeding up, the acceleration available falls as a_max·(1 − |v| / this);
  // braking, the back-EMF helps and the current limit a_max holds.
  double backemf_speed_mm_s = 0;
  // Thermal (RMS current) limit: the drive trips, and the laser goes off for the rest of the job,
  // when an axis's rms acceleration over the coil's thermal time constant (an exponential window)
  // passes this share of its peak acceleration. 0 %: none.
  double rms_accel_pct = 0;
  double thermal_tau_s = 1;
  // The amplifier's current loop (0 µs: none, the current — the acceleration — is what the servo
  // asks at once). With it, the servo's velocity loop asks for an acceleration
  // (want − v) / (4·τi), critically damped with the current loop, and the current follows that
  // demand with the loop's lag τi; a first-order head stays first order on a ramp (the same lag
  // v·τ) but its corners and jumps ring.
  double current_tau_us = 0;
  // With the current loop: how fast the current may change (the supply voltage over the coil's
  // inductance), as a jerk limit on the mirror, mm/s³ (0: none).
  double jerk_max_mm_s3 = 0;
  // Beam position noise: rms per axis, correlated over the servo's τ (an Ornstein–Uhlenbeck
  // process), from a generator seeded with `seed` at every job's start.
  double noise_um = 0;
  std::uint64_t seed = 1;
  // Command quantisation: every sample rounded to one of 2^bits codes across the field (XY2-100:
  // 16). 0: exact.
  int quant_bits = 0;

  // True when it adds nothing to the preset.
  bool is_model() const {
    return tau_scale == 1 && wn_scale == 1 && dead_us == 0 && latency_us == 0 && resonance_hz == 0 && accel_max_mm_s2 == 0 &&
           backemf_speed_mm_s == 0 && rms_accel_pct == 0 && current_tau_us == 0 && jerk_max_mm_s3 == 0 && noise_um == 0 &&
           quant_bits == 0;
  }
};

}  // namespace mark
