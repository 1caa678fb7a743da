#include "marker/cli/gravure_options.hpp"

#include <sstream>
#include <vector>

#include "base/error.hpp"
#include "marker/limits/gravure_settings.hpp"

namespace mark::cli {
namespace {

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, sep)) parts.push_back(part);
  if (text.empty() || text.back() == sep) parts.push_back("");  // "1:2:" has an empty third part
  return parts;
}

// The numbers of "a:b:c" (separator `sep`); throws naming the option and the expected form.
std::vector<double> numbers(const std::string& option, const std::string& text, char sep, std::size_t min_count,
                            std::size_t max_count, const std::string& form) {
  const std::vector<std::string> parts = split(text, sep);
  if (parts.size() < min_count || parts.size() > max_count)
    throw InputError(option + " '" + text + "': expected " + form);
  std::vector<double> out;
  for (const std::string& part : parts) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (part.empty() || used != part.size())
      throw InputError(option + " '" + text + "': '" + part + "' is not a number; expected " + form);
    out.push_back(v);
  }
  return out;
}

}  // namespace

void parse_screen(const std::string& option, const std::string& text, GravureScreen& screen) {
  const std::vector<double> v = numbers(option, text, 'x', 1, 2, "LINES_PER_CM or ALONGxACROSS, e.g. 70 or 70x60");
  const Range lines{kCellsPerMmBounds.range().min * 10, kCellsPerMmBounds.range().max * 10, "lines/cm"};
  check_range(option + " along", v[0], lines);
  const double across = v.size() == 2 ? v[1] : v[0];
  check_range(option + " across", across, lines);
  screen.cells_per_mm_along = v[0] / 10;
  screen.cells_per_mm_across = across / 10;
}

StylusHeadModel parse_head(const std::string& option, const std::string& text) {
  StylusHeadModel head;
  const std::string form = "FREQ_HZ:DAMPING:GAIN[,FREQ_HZ:DAMPING:GAIN...], e.g. 1800:0.06:0.8,5500:0.04:0.2";
  const std::vector<std::string> modes = split(text, ',');
  if (modes.size() > 4) throw InputError(option + " '" + text + "': at most 4 resonances");
  for (std::size_t i = 0; i < modes.size(); ++i) {
    const std::vector<double> v = numbers(option, modes[i], ':', 3, 3, form);
    const std::string at = option + " resonance " + std::to_string(i + 1);
    check_range(at + " frequency", v[0], kModeFrequencyBounds.range());
    check_range(at + " damping", v[1], kModeDampingBounds.range());
    check_range(at + " gain", v[2], kModeGainBounds.range());
    head.modes.push_back({v[0], v[1], v[2]});
  }
  return head;
}

FilterSection parse_notch(const std::string& option, const std::string& text) {
  const std::vector<double> v = numbers(option, text, ':', 3, 3, "FREQ_HZ:DAMPING:DEPTH_DB, e.g. 1800:0.06:18");
  check_range(option + " frequency", v[0], kFilterFrequencyBounds.range());
  check_range(option + " damping", v[1], {kPoleDampingBounds.range().min, 1, ""});
  check_range(option + " depth", v[2], kNotchDepthBounds.range());
  const FilterSection s = notch_section(v[0], v[1], v[2]);
  check_range(option + " damping × depth (the notch's pole damping)", s.pole_damping, kPoleDampingBounds.range());
  return s;
}

FilterSection parse_emphasis(const std::string& option, const std::string& text) {
  const std::vector<double> v =
      numbers(option, text, ':', 4, 4, "FREQ_HZ:DAMPING:CORNER_HZ:CORNER_DAMPING, e.g. 5500:0.5:20000:0.707");
  check_range(option + " frequency", v[0], kFilterFrequencyBounds.range());
  check_range(option + " damping", v[1], kZeroDampingBounds.range());
  check_range(option + " corner frequency", v[2], kFilterFrequencyBounds.range());
  check_range(option + " corner damping", v[3], kPoleDampingBounds.range());
  return emphasis_section(v[0], v[1], v[2], v[3]);
}

}  // namespace mark::cli
