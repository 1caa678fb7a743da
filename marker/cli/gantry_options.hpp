#pragma once
// Command-line options for the simulated pin-marker gantry: every parameter of the time model,
// for both axes at once or per axis (the per-axis option wins).
#include <CLI/CLI.hpp>
#include <optional>

#include "marker/peen/gantry.hpp"

namespace mark::cli {

struct GantryArgs {
  std::optional<double> steps_per_mm, x_steps_per_mm, y_steps_per_mm;
  std::optional<double> speed_mm_s, x_speed_mm_s, y_speed_mm_s;
  std::optional<double> accel_mm_s2, x_accel_mm_s2, y_accel_mm_s2;
  std::optional<double> strike_ms;
};

void add_gantry_options(CLI::App& app, GantryArgs& args);
// The default gantry with the given overrides; throws InputError for an impossible value.
GantryConfig to_gantry(const GantryArgs& args);

}  // namespace mark::cli
