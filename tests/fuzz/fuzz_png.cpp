// libFuzzer target for the PNG reader (marker/image/, decode_png); see fuzz_image.hpp for what
// counts as a bug. scripts/fuzz.sh runs it with -rss_limit_mb and -timeout: a file whose
// decoding costs more than its declared size allows (a bomb) fails the run.
#include "fuzz_image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mark::fuzz::run_image_reader(data, size, mark::decode_png, "fuzz.png");
}
