#pragma once
// The simulated head every command that drives one shares: --head (preset), --head-model
// (the real head's servo: its preset's own, first or second order), --head-zeta (damping of a
// second-order servo) and, where a laser fires, --laser-rise-us (the laser power's first-order
// rise and fall time) and --plant (the simulated head apart from the planner's model of it).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "driver/sim/head_model.hpp"
#include "marker/limits/head_settings.hpp"

namespace mark::cli {

struct HeadArgs {
  std::string head{kHead.value};  // defaults from marker/limits/head_settings.hpp
  std::string model;             // "", "first" or "second"
  std::optional<double> zeta;    // second-order damping (default: the preset's)
  double laser_rise_us = *kLaserRise.value;
  std::string plant;             // --plant KEY=VALUE,… ("": the preset itself)
};

void add_head_options(CLI::App& app, HeadArgs& args, bool laser);

// The preset with the options applied; throws InputError naming a bad option and its range.
HeadModel simulated_head(const HeadArgs& args);

// "--head SL10 --head-model second ..." for the options that differ from the defaults, so a
// printed command line reproduces the head.
std::string head_args_string(const HeadArgs& args);

}  // namespace mark::cli
