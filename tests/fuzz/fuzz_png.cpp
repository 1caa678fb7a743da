// libFuzzer target for the PNG reader (marker/image/, decode_png): every input either throws
// InputError naming the source, or returns an image downstream code can trust — width × height
// pixels, every intensity finite and within 0 .. 1, no more pixels than the reader's limit.
// scripts/fuzz.sh runs it with -rss_limit_mb and -timeout: a file whose decoding costs more than
// its declared size allows (a bomb) fails the run. Anything else (a crash, a sanitizer report,
// another exception, a broken invariant) is a bug.
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "fonts/error.hpp"
#include "fuzz_check.hpp"
#include "marker/image/gray_image.hpp"

using mark::fuzz::broken;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const mark::GrayImage img = mark::decode_png(bytes, "fuzz.png");
    if (img.width < 1 || img.height < 1) broken("empty image returned");
    if (static_cast<std::int64_t>(img.width) * img.height > mark::kMaxImagePixels) broken("image over the limit");
    if (img.pixels.size() != static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height))
      broken("pixel count differs from width × height");
    for (float v : img.pixels)
      if (!std::isfinite(v) || v < 0 || v > 1) broken("intensity outside 0 .. 1");
  } catch (const mark::InputError& e) {
    if (std::string(e.what()).rfind("fuzz.png: ", 0) != 0) broken("error does not name the source");
  }
  return 0;
}
