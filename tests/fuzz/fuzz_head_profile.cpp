// libFuzzer target for the head's files, each input read as both: parse_head_profile either
// throws InputError (a bad file, reported with its key and range) or returns a profile the
// planner can trust — the chosen model's time constants and both limits finite and positive, its
// ramp lag positive, a resonance none or within a shaper's range; parse_lag_pattern either throws InputError or returns a pattern of four
// lines per speed and two corners per corner speed, every end finite. Anything else (a crash, a sanitizer report, another
// exception, a broken invariant) is a bug.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "base/error.hpp"
#include "marker/head/head_profile.hpp"
#include "marker/head/lag_pattern.hpp"

namespace {

[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}

bool positive(double v) { return std::isfinite(v) && v > 0; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const mark::HeadProfile p = mark::parse_head_profile(text, "fuzz.json");
    if (!positive(p.lag_s())) broken("ramp lag not positive");
    if (!std::isfinite(p.inertia_s2()) || p.inertia_s2() < 0) broken("inverse-filter term invalid");
    if (!positive(p.max_speed_mm_s) || !positive(p.max_accel_mm_s2)) broken("limits not positive");
    if (!positive(p.field_mm) || !positive(p.tick_s)) broken("field or tick not positive");
    // A resonance is none (0) or one a shaper can be designed for: 100 Hz .. 250 kHz, ζ 0 .. 0.5.
    if (p.resonance_hz != 0 && !(p.resonance_hz >= 100 && p.resonance_hz <= 250000)) broken("resonance out of range");
    if (!(p.resonance_zeta >= 0 && p.resonance_zeta <= 0.5)) broken("resonance damping out of range");
  } catch (const mark::InputError&) {
  }
  try {
    const mark::LagPattern p = mark::parse_lag_pattern(text, "fuzz.json");
    if (p.lines.size() != 4 * p.speeds_mm_s.size()) broken("not four lines per speed");
    for (const mark::LagLine& l : p.lines)
      if (!std::isfinite(l.start.x) || !std::isfinite(l.start.y) || !std::isfinite(l.end.x) ||
          !std::isfinite(l.end.y) || !positive(l.speed_mm_s))
        broken("a line's end or speed is not finite");
    if (p.corners.size() != 2 * p.corner_speeds_mm_s.size()) broken("not two corners per corner speed");
    for (const mark::LagCorner& c : p.corners)
      if (!std::isfinite(c.end.x) || !std::isfinite(c.end.y) || !positive(c.speed_mm_s))
        broken("a corner's end or speed is not finite");
  } catch (const mark::InputError&) {
  }
  return 0;
}
