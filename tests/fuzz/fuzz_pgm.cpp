// libFuzzer target for parse_pgm, the tool-measure image reader's own parser. A malformed file
// must be an InputError; an image that parses must hold width × height samples, all in 0..1, and
// never more pixels than the reader's limit.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "fonts/error.hpp"
#include "marker/cnc/tool/gray_image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const mark::GrayImage img = mark::parse_pgm(bytes, "fuzz.pgm");
    const auto n = static_cast<std::int64_t>(img.width) * img.height;
    if (img.width < 1 || img.height < 1 || n > mark::kMaxImagePixels ||
        static_cast<std::int64_t>(img.pixels.size()) != n) {
      std::fprintf(stderr, "fuzz invariant broken: %dx%d image with %zu samples\n", img.width, img.height,
                   img.pixels.size());
      std::abort();
    }
    for (float v : img.pixels)
      if (!(v >= 0.0f && v <= 1.0f)) {
        std::fprintf(stderr, "fuzz invariant broken: sample %g outside 0..1\n", v);
        std::abort();
      }
  } catch (const mark::InputError&) {
    // A reported malformed file.
  }
  return 0;
}
