#include "marker/cli/head_options.hpp"

#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/head/head_profile.hpp"

namespace mark::cli {
namespace {

const Range kZetaRange{0.05, 10, ""};
const Range kLaserRiseRange{0, 1000, "µs"};

}  // namespace

void add_head_options(CLI::App& app, HeadArgs& a, bool laser) {
  std::string names;
  for (const std::string& n : head_names()) names += (names.empty() ? "" : ", ") + n;
  app.add_option("--head", a.head, "scan head preset: " + names)->capture_default_str();
  app.add_option("--head-model", a.model,
                 "the simulated head's servo: first or second order (default: the preset's)");
  add_ranged_option(app, "--head-zeta", a.zeta, "damping ζ of a second-order servo (default: the preset's)",
                    kZetaRange);
  if (laser)
    add_ranged_option(app, "--laser-rise-us", a.laser_rise_us, "laser power rise and fall time constant, µs (0: instant)",
                      kLaserRiseRange)
        ->capture_default_str();
}

HeadModel simulated_head(const HeadArgs& a) {
  const auto preset = find_head(a.head);
  if (!preset) {
    std::string names;
    for (const std::string& n : head_names()) names += (names.empty() ? "" : ", ") + n;
    throw InputError("--head '" + a.head + "' is not one of " + names);
  }
  HeadModel h = *preset;
  if (!a.model.empty()) {
    if (a.model != "first" && a.model != "second")
      throw InputError("--head-model '" + a.model + "' is not one of first, second");
    h.second_order = parse_servo_order(a.model) == ServoOrder::second;
  }
  // Checked while parsing too; a caller from code gets the same words.
  if (a.zeta) {
    check_range("--head-zeta", *a.zeta, kZetaRange);
    h.zeta = *a.zeta;
  }
  check_range("--laser-rise-us", a.laser_rise_us, kLaserRiseRange);
  return h;
}

std::string head_args_string(const HeadArgs& a) {
  std::ostringstream s;
  s << "--head " << a.head;
  if (!a.model.empty()) s << " --head-model " << a.model;
  if (a.zeta) s << " --head-zeta " << *a.zeta;
  if (a.laser_rise_us > 0) s << " --laser-rise-us " << a.laser_rise_us;
  return s.str();
}

}  // namespace mark::cli
