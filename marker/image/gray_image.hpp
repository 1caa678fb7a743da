#pragma once
// A grey-level image — a tool's shadow, gravure artwork, a line-work mask — intensities 0 (dark)
// .. 1 (bright), row-major, row 0 at the top. Read from PNG (through Cairo) or PGM (P2 ASCII /
// P5 binary, our own parser); the format is recognised by the file's first bytes, not its name.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mark {

struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<float> pixels;
  float at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// Images larger than this many pixels are refused (a hostile header must not allocate gigabytes).
inline constexpr std::int64_t kMaxImagePixels = 100'000'000;

// Throws InputError naming the file and what is wrong (unknown format, malformed or truncated
// PGM, unreadable PNG).
GrayImage read_gray_image(const std::string& path);

// PGM from memory; `source` names it in messages.
GrayImage parse_pgm(std::string_view bytes, const std::string& source);

}  // namespace mark
