#include "marker/cli/head_options.hpp"

#include <cmath>
#include <sstream>

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/head/head_profile.hpp"
#include "marker/limits/head_settings.hpp"

namespace mark::cli {

void add_head_options(CLI::App& app, HeadArgs& a, bool laser) {
  add_setting(app, kHead, a.head);
  add_setting(app, kHeadModel, a.model);
  add_setting(app, kHeadZeta, a.zeta);
  if (laser) {
    add_setting(app, kLaserRise, a.laser_rise_us);
    add_setting(app, kPlant, a.plant);
  }
}

HeadModel simulated_head(const HeadArgs& a) {
  const auto preset = find_head(a.head);
  if (!preset) {
    std::string names;
    for (const std::string& n : head_names()) names += (names.empty() ? "" : ", ") + n;
    throw InputError("--head '" + a.head + "' is not one of " + names);
  }
  HeadModel h = *preset;
  if (!a.model.empty()) h.second_order = parse_servo_order(a.model) == ServoOrder::second;
  // Checked while parsing too; a caller from code gets the same words.
  if (a.zeta) {
    check_setting(kHeadZeta, *a.zeta);
    // A first-order head has no damping: the value would be accepted and change nothing.
    if (!h.second_order)
      throw InputError(flag(kHeadZeta) + " does not apply: head " + h.name + " is first order (give " +
                       flag(kHeadModel) + " second)");
    h.zeta = *a.zeta;
  }
  check_setting(kLaserRise, a.laser_rise_us);
  return h;
}

std::string head_args_string(const HeadArgs& a) {
  std::ostringstream s;
  s << kHead.name.flag << " " << a.head;
  if (!a.model.empty()) s << " " << kHeadModel.name.flag << " " << a.model;
  if (a.zeta) s << " " << kHeadZeta.name.flag << " " << *a.zeta;
  if (a.laser_rise_us > 0) s << " " << kLaserRise.name.flag << " " << a.laser_rise_us;
  if (!a.plant.empty()) s << " " << kPlant.name.flag << " " << a.plant;
  return s.str();
}

}  // namespace mark::cli
