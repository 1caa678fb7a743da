#include "driver/laser_source.hpp"

#include <cmath>
#include <cstdio>

#include "base/error.hpp"

namespace mark {
namespace {

[[noreturn]] void refuse(std::string_view where, const char* text) {
  throw InputError(std::string(where) + text);
}

}  // namespace

const SourceLimits& limits_of(LaserSource source) {
  for (const SourceLimits& s : kLaserSources)
    if (s.source == source) return s;
  return kLaserSources[0];  // unreachable: every enumerator has its row
}

std::string_view to_string(LaserSource source) { return limits_of(source).name; }

std::optional<LaserSource> parse_laser_source(std::string_view name) {
  for (const SourceLimits& s : kLaserSources)
    if (s.name == name) return s.source;
  return std::nullopt;
}

std::string laser_source_names() {
  std::string out;
  for (const SourceLimits& s : kLaserSources) {
    if (!out.empty()) out += ", ";
    out += s.name;
  }
  return out;
}

void check_laser_settings(const LaserSettings& l, std::string_view where) {
  const SourceLimits& s = limits_of(l.source);
  char buf[240];
  if (!(l.power_pct >= 0 && l.power_pct <= 100)) {
    std::snprintf(buf, sizeof buf, "power %g %% is outside 0 .. 100 %%", l.power_pct);
    refuse(where, buf);
  }
  if (!(l.frequency_khz >= s.min_frequency_khz && l.frequency_khz <= s.max_frequency_khz)) {
    std::snprintf(buf, sizeof buf, "frequency %g kHz is outside what a %s source runs (%s: %g .. %g kHz)",
                  l.frequency_khz, std::string(s.name).c_str(), std::string(s.description).c_str(),
                  s.min_frequency_khz, s.max_frequency_khz);
    refuse(where, buf);
  }
  if (l.pulse_width_ns == 0) return;  // the source's own pulse, whatever the source
  if (!s.pulse_width) {
    const SourceLimits& mopa = limits_of(LaserSource::mopa);
    std::snprintf(buf, sizeof buf,
                  "pulse width %g ns: a %s source (%s) has no settable pulse width (only mopa: "
                  "%g .. %g ns; 0 for the source's own)",
                  l.pulse_width_ns, std::string(s.name).c_str(), std::string(s.description).c_str(),
                  mopa.min_pulse_width_ns, mopa.max_pulse_width_ns);
    refuse(where, buf);
  }
  if (!(l.pulse_width_ns >= s.min_pulse_width_ns && l.pulse_width_ns <= s.max_pulse_width_ns)) {
    std::snprintf(buf, sizeof buf,
                  "pulse width %g ns is outside what a %s source takes (%g .. %g ns; 0 for the "
                  "source's own)",
                  l.pulse_width_ns, std::string(s.name).c_str(), s.min_pulse_width_ns,
                  s.max_pulse_width_ns);
    refuse(where, buf);
  }
}

}  // namespace mark
