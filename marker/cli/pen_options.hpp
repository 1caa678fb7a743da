#pragma once
// The options that choose the device side of a simulated mark — head preset, field, corner
// strategy, speeds, tick, blanking extensions — shared by the commands that mark on the
// simulated scanner (`code` now; `mark` keeps its own until the job runner's rework lands).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "driver/head_model.hpp"
#include "marker/plan/pen.hpp"

namespace mark::cli {

struct PenArgs {
  std::string head = "SL10";
  std::string corner = "blanking";
  double speed_mm_s = 1000;
  double jump_speed_mm_s = 0;  // 0: the head's default
  double tick_us = 10;
  std::optional<double> run_in_mm;
  std::optional<double> run_out_mm;
  double field_mm = 110;
};

void add_pen_options(CLI::App& app, PenArgs& args);

struct HeadAndPen {
  HeadModel head;
  Pen pen;
};

// Throws InputError naming the option for an unknown head or strategy or a value out of range.
HeadAndPen make_head_and_pen(const PenArgs& args);

}  // namespace mark::cli
