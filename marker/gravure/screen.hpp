#pragma once
// The gravure screen: how many cells per millimetre along the track (around the cylinder) and
// across it (one track per cell row, the head advancing one track pitch a revolution), how many
// cells the stylus engraves a second, and whether odd tracks are staggered by half a cell (the
// usual compressed / elongated screens interleave cells of neighbouring tracks).
#include <cstdint>

namespace mark {

struct GravureScreen {
  double cells_per_mm_along = 7;    // 70 lines/cm
  double cells_per_mm_across = 7;
  std::uint32_t cell_rate_hz = 6250;  // 32 stylus samples a cell at 200 kHz
  bool stagger = false;

  double cell_pitch_um() const { return 1000 / cells_per_mm_along; }
  double track_pitch_um() const { return 1000 / cells_per_mm_across; }
};

// Throws InputError naming the field and its range.
void validate(const GravureScreen& screen);

}  // namespace mark
