// libFuzzer target for parse_cxf (see fuzz_font.hpp for what counts as a bug).
#include "fuzz_font.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return mark::fuzz::run(data, size, mark::parse_cxf, "fuzz.cxf");
}
