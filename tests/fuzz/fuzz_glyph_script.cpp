// libFuzzer target for parse_glyph_script, the built-in font's drawing language. A bad script must
// be an InputError; a glyph that parses must have finite geometry, lit elements of positive
// length and a pen path without gaps (the same invariants as every font loader, fuzz_font.hpp).
#include <cstdint>
#include <string_view>

#include "fonts/builtin/glyph_script.hpp"
#include "fuzz_font.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view script(reinterpret_cast<const char*>(data), size);
  try {
    mark::FontMetrics m;
    m.cap_height = m.standard_height = m.ascender = 10;
    m.line_height = 16;
    mark::StrokeFont font("fuzz", "fuzz", m);
    font.add(mark::parse_glyph_script(U'A', 8, script));
    mark::fuzz::check_font(font);
  } catch (const mark::InputError&) {
    // A reported bad script.
  }
  return 0;
}
