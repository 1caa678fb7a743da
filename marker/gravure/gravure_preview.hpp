#pragma once
// The proof of a gravure job: the cylinder surface seen from above, intended cells on the left
// and engraved cells on the right at the same scale. Each cell is drawn as its opening on the
// surface — as wide as the diamond cuts at that depth (2·depth·tan(θ/2)) — shaded by depth
// (deeper is darker), so missing highlights, merged channels and shifted cells show at a glance.
#include <cstdint>
#include <span>
#include <string>

namespace mark {

struct GravureLayout {
  std::uint32_t tracks = 1;
  std::uint32_t cells_per_track = 1;
  double cell_pitch_um = 100;
  double track_pitch_um = 100;
  bool stagger = false;
  std::uint32_t cell_rate_hz = 6250;
  double stylus_angle_deg = 120;
};

// PNG or SVG by the file's extension; written under a temporary name and renamed. Throws
// InputError naming the file on failure.
void write_gravure_preview(const GravureLayout& layout, std::span<const float> intended_um,
                           std::span<const float> engraved_um, const std::string& path);

}  // namespace mark
