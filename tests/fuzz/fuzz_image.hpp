#pragma once
// What every image-reader fuzz target checks (fuzz_pgm, fuzz_png): the reader either throws
// InputError naming the source, or returns an image downstream code can trust — width × height
// pixels, every intensity finite and within 0 .. 1, no more pixels than the reader's limit.
// Anything else (a crash, a sanitizer report, another exception, a broken invariant) is a bug.
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "base/error.hpp"
#include "fuzz_check.hpp"
#include "marker/image/gray_image.hpp"

namespace mark::fuzz {

template <class Read>
int run_image_reader(const std::uint8_t* data, std::size_t size, Read read, const std::string& source) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const GrayImage img = read(bytes, source);
    if (img.width < 1 || img.height < 1) broken("empty image returned");
    if (static_cast<std::int64_t>(img.width) * img.height > kMaxImagePixels) broken("image over the limit");
    if (img.pixels.size() != static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height))
      broken("pixel count differs from width × height");
    for (float v : img.pixels)
      if (!std::isfinite(v) || v < 0 || v > 1) broken("intensity outside 0 .. 1");
  } catch (const InputError& e) {
    if (std::string(e.what()).rfind(source + ": ", 0) != 0) broken("error does not name the source");
  }
  return 0;
}

}  // namespace mark::fuzz
