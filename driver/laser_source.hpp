#pragma once
// The laser sources the engine drives, defined once for every part of it: a pen's `source` and
// its laser settings (power, frequency, pulse width), what each source accepts, and the one check
// of a pen's settings against its source. The LMC board sends each source its own words
// (driver/lmc/job_encoder.hpp); the simulator's pulse model reads the same definition.
//
// The ranges are generous on purpose: they refuse what a source of that kind cannot do at all (a
// pulse width on a Q-switched or CO2 source, 5 MHz on a Q-switched fiber), not what one model on
// the market happens not to do. Sources and confidence: docs/lmc.md, "Laser sources".
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace mark {

enum class LaserSource : std::uint8_t {
  fiber,  // Q-switched ytterbium fiber (1064 nm): pulses at the Q-switch frequency, fixed width
  mopa,   // MOPA fiber: repetition rate and pulse width set independently
  co2,    // RF-excited CO2 (10.6 µm): continuous wave, its power a PWM duty at the frequency
  uv      // DPSS UV (355 nm), Q-switched: pulses at the frequency, fixed width
};

struct SourceLimits {
  LaserSource source;
  std::string_view name;         // as `--source` and a pen's "source" take it
  std::string_view description;  // for help and messages
  double min_frequency_khz, max_frequency_khz;
  // false: a continuous-wave source; its frequency is the carrier of the PWM that sets its
  // power, not a train of separate pulses.
  bool pulsed;
  bool pulse_width;              // a settable pulse width (MOPA only)
  double min_pulse_width_ns, max_pulse_width_ns;
  // Fiber sources have a master oscillator the board opens for a job (Fiber_SetMo) and needs an
  // open-MO delay before the first pulse; CO2 and UV have none.
  bool master_oscillator;
};

inline constexpr SourceLimits kLaserSources[] = {
    {LaserSource::fiber, "fiber", "Q-switched fiber", 1, 200, true, false, 0, 0, true},
    {LaserSource::mopa, "mopa", "MOPA fiber", 1, 4000, true, true, 2, 500, true},
    {LaserSource::co2, "co2", "CO2 (continuous wave, PWM power)", 1, 100, false, false, 0, 0, false},
    {LaserSource::uv, "uv", "Q-switched UV (DPSS)", 10, 300, true, false, 0, 0, false},
};

const SourceLimits& limits_of(LaserSource source);
std::string_view to_string(LaserSource source);
// "fiber", "mopa", "co2", "uv"; nullopt for anything else.
std::optional<LaserSource> parse_laser_source(std::string_view name);
// "fiber, mopa, co2, uv", for messages and help.
std::string laser_source_names();

// Laser settings of a pen. (The source last: {power, frequency, pulse width} still reads as it
// did before there were sources.)
struct LaserSettings {
  double power_pct = 100;       // 0..100 % of the source's power
  double frequency_khz = 30;    // pulse repetition rate (Q-switch), or the CO2 PWM carrier
  double pulse_width_ns = 0;    // MOPA pulse width; 0 = the source's default (any source)
  LaserSource source = LaserSource::fiber;
};

// Refuses settings the pen's source cannot take, in one line after `where` (e.g. "pen 0: " or
// "--source co2: "): a power outside 0..100 %, a frequency outside the source's range, a pulse
// width on a source that has none. Throws InputError.
void check_laser_settings(const LaserSettings& settings, std::string_view where = {});

}  // namespace mark
