#pragma once
// The head response test of the seed (FIG. 7 block 214, FIG. 8 blocks 232–234): a test pattern
// is sent to the head instead of the toolpath and the sensing coil's position and velocity
// (FIG. 13–14) are read back. The pattern is a stepped-sine sweep — one tone after another,
// log-spaced — held above the cylinder surface so the test cuts nothing. Each tone plays long enough for the head's
// ringing from the previous tone to die away, then the response is measured over the rest of
// the tone by a least-squares sine fit (offset + cosine + sine at the tone's frequency, the
// IEEE 1057 three-parameter fit: exact for any tone length, insensitive to the offset).
//
// Position and velocity give two estimates of the same position response: the position's sine
// fit directly, the velocity's divided by jω. Their noises differ in kind — the position's is
// a fixed displacement, worst at high frequency where the head moves little; the velocity's a
// fixed speed, worst at low frequency where the head moves slowly — so each tone takes both,
// weighted by the inverse of their variances (each from its own fit's residual): the fused
// estimate is never worse than the better one. The velocity estimate is not quite the position
// response: the held (DAC) drive's images (200 kHz ± f) move the stylus between samples, and
// their velocity, sampled, folds onto the tone — 1.3 % of the response at 10 kHz, 2 % at 16 kHz
// on the typical head. So each point says how much of it came from the velocity, and
// point_response() gives what a head model shows at that point, which the fit compares with.
#include <complex>
#include <span>
#include <string_view>
#include <vector>

#include "driver/sim/stylus_head_model.hpp"
#include "marker/gravure/drive_source.hpp"

namespace mark {

struct SweepOptions {
  double start_hz = 200;
  double stop_hz = 16000;
  int tones = 80;
  double amplitude_um = 1;   // small signal: the peaks of a ζ = 0.04 mode still stay within ±13 µm
  double offset_um = -30;    // held above the surface
  double settle_s = 0.015;   // ≥ 9 time constants of a 1.8 kHz, ζ = 0.06 resonance
  double measure_s = 0.010;
};

// Throws InputError for an impossible sweep (frequencies outside 10 Hz .. 45 kHz or not
// ascending, fewer than 8 tones, non-positive times or amplitude).
void validate(const SweepOptions& sweep);

struct ResponsePoint {
  double freq_hz = 0;
  std::complex<double> gain;  // sensed position over commanded drive
  double sigma = 0;           // standard error of `gain` (from the sine fit's residual)
  double velocity_weight = 0; // share of the velocity estimate in `gain`: 0 position only .. 1
};

// What `head` shows at `point`: its held position response, mixed by the point's velocity_weight
// with its held velocity response over jω (driver/sim/stylus_head_model.hpp).
std::complex<double> point_response(const StylusHeadModel& head, const ResponsePoint& point);

// Which signals of the sensing coil a response is measured from.
enum class ResponseSource { position, velocity, fused };
std::string_view to_string(ResponseSource source);  // "position", "velocity", "both" (as --tune-from)

// Per tone, the inverse-variance mean of two estimates of the same response (same tones, in the
// same order); a tone where one estimate has zero uncertainty takes that one (both zero: the
// mean). Throws InputError when the two do not have the same tones.
std::vector<ResponsePoint> fuse(std::span<const ResponsePoint> position, std::span<const ResponsePoint> velocity);

class SweepPattern : public DriveSource {
 public:
  explicit SweepPattern(const SweepOptions& options);
  std::uint64_t total_samples() const override { return total_; }
  std::size_t next(std::span<double> out) override;
  void rewind() { at_ = 0; }

  // The response at every tone from the sensed position recorded while the pattern played
  // (sample k of `sensed` answers sample k of the pattern).
  std::vector<ResponsePoint> measure(std::span<const float> sensed_um) const;
  // The same from the sensed velocity: its response divided by jω (velocity_weight 1).
  std::vector<ResponsePoint> measure_velocity(std::span<const float> sensed_um_s) const;
  // From both, fused per tone (see fuse()).
  std::vector<ResponsePoint> measure(std::span<const float> sensed_um, std::span<const float> sensed_um_s) const;

  double duration_s() const;
  const SweepOptions& options() const { return options_; }

 private:
  struct Tone {
    double freq_hz;
    std::uint64_t start, settle, length;  // first sample, samples before measuring, samples
  };
  double value(std::uint64_t sample) const;
  // The tone's complex amplitude in `signal` (Re{y e^{jωn}}) and its standard error.
  struct ToneFit {
    std::complex<double> y;
    double sigma;
  };
  ToneFit fit_tone(const Tone& tone, std::span<const float> signal) const;
  void check_length(std::span<const float> signal, const char* what) const;

  SweepOptions options_;
  std::vector<Tone> tones_;
  std::uint64_t total_ = 0;
  std::uint64_t at_ = 0;
  std::size_t tone_ = 0;  // cursor for next()
};

}  // namespace mark
