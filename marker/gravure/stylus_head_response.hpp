#pragma once
// The head response test of the seed (FIG. 7 block 214, FIG. 8 blocks 232–234): a test pattern
// is sent to the head instead of the toolpath and the sensing coil's position (FIG. 13–14) is
// read back. The pattern is a stepped-sine sweep — one tone after another, log-spaced — held
// above the cylinder surface so the test cuts nothing. Each tone plays long enough for the head's
// ringing from the previous tone to die away, then the response is measured over the rest of
// the tone by a least-squares sine fit (offset + cosine + sine at the tone's frequency, the
// IEEE 1057 three-parameter fit: exact for any tone length, insensitive to the offset).
#include <complex>
#include <span>
#include <vector>

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
};

class SweepPattern : public DriveSource {
 public:
  explicit SweepPattern(const SweepOptions& options);
  std::uint64_t total_samples() const override { return total_; }
  std::size_t next(std::span<double> out) override;
  void rewind() { at_ = 0; }

  // The response at every tone from the sensed position recorded while the pattern played
  // (sample k of `sensed` answers sample k of the pattern).
  std::vector<ResponsePoint> measure(std::span<const float> sensed_um) const;

  double duration_s() const;
  const SweepOptions& options() const { return options_; }

 private:
  struct Tone {
    double freq_hz;
    std::uint64_t start, settle, length;  // first sample, samples before measuring, samples
  };
  double value(std::uint64_t sample) const;

  SweepOptions options_;
  std::vector<Tone> tones_;
  std::uint64_t total_ = 0;
  std::uint64_t at_ = 0;
  std::size_t tone_ = 0;  // cursor for next()
};

}  // namespace mark
