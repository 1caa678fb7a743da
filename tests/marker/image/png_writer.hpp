#pragma once
// Test support: PNG files of every colour type, depth and interlacing, written with libpng's
// writer into memory, from a function giving each pixel's samples. The reader under test and the
// reference decoder (cairo) both read these.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mark::test {

struct PngSpec {
  int width = 1, height = 1;
  int colour_type = 0;  // PNG_COLOR_TYPE_GRAY (0), _RGB (2), _PALETTE (3), _GRAY_ALPHA (4), _RGB_ALPHA (6)
  int bit_depth = 8;    // 1, 2, 4, 8, 16 as the colour type allows
  bool interlaced = false;
  // Samples of pixel (x, y), one per channel, each 0 .. 2^depth − 1 (palette: the index).
  std::function<std::vector<unsigned>(int x, int y)> pixel;
  // Palette images: the palette (r, g, b) and the alpha of the first entries (tRNS), if any.
  std::vector<std::uint8_t> palette_rgb;
  std::vector<std::uint8_t> palette_alpha;
  // Grey or RGB images: the colour key that is transparent (tRNS), if set.
  std::vector<unsigned> transparent_key;
};

std::string write_png(const PngSpec& spec);

// A PNG file's bytes that declare `width` x `height` 8-bit grey pixels and carry no image data
// (signature, IHDR, IEND): what a reader that checks the header first refuses at once.
std::string png_header_only(std::uint32_t width, std::uint32_t height);

}  // namespace mark::test
