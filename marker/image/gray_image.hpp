#pragma once
// A grey-level image — a tool's shadow, gravure artwork, a line-work mask — intensities 0 (dark)
// .. 1 (bright), row-major, row 0 at the top. Read from PNG (libpng, any colour type and depth:
// colour as luma, alpha over white) or PGM (P2 ASCII / P5 binary, our own parser); the format is
// recognised by the file's first bytes, not its name. Both readers check the size the header
// declares against kMaxImagePixels, and against what the file can hold, before they decode a
// pixel, and decode into the image directly: a hostile header costs nothing, a real image costs
// its own size (4 bytes a pixel) plus one row.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mark {

class ImageSource;

struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<float> pixels;
  float at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// Images larger than this many pixels are refused (a hostile header must not allocate gigabytes).
inline constexpr std::int64_t kMaxImagePixels = 100'000'000;

// Every caller that reads an image file (gravure IMAGE and --mask, gcode --tool-image,
// tool-measure) comes here. Throws InputError, one line naming the file ('path': ...) and what is
// wrong: cannot open, unknown format, a size over the limit, malformed or truncated data.
GrayImage read_gray_image(const std::string& path);

// The readers on their own; `name` begins every message.
GrayImage read_pgm(ImageSource& source, const std::string& name);
GrayImage read_png(ImageSource& source, const std::string& name);
// The same from memory (tests, fuzz targets); `source` names the bytes in messages.
GrayImage parse_pgm(std::string_view bytes, const std::string& source);
GrayImage decode_png(std::string_view bytes, const std::string& source);

}  // namespace mark
