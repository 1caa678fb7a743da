// libFuzzer target for parse_pgm (marker/image/); see fuzz_image.hpp for what counts as a bug.
#include "fuzz_image.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mark::fuzz::run_image_reader(data, size, mark::parse_pgm, "fuzz.pgm");
}
