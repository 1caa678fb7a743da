#pragma once
// One point of locus: where the mirrors should be at this tick, and whether the laser is on.
// Field frame in millimetres (origin at the field centre); devices convert to their own units at
// the edge. 12 bytes, so the line memory stays cache-friendly at 100 kHz and above.
#include <cstdint>

namespace mark {

struct ScanSample {
  float x_mm = 0;
  float y_mm = 0;
  bool laser = false;
  std::uint8_t power = 255;  // 0..255 of the pen's power, where the device supports it
};

// The safe sample (ringbuffer/sample_traits.hpp): stay at the last position with the laser off.
inline ScanSample safe_sample(const ScanSample& last) {
  ScanSample s = last;
  s.laser = false;
  return s;
}

}  // namespace mark
