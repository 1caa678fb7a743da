#pragma once
// A subcommand: `attach` adds it and its options to the app; `run` executes it after parsing.
// Each command's file defines one `Command make_<name>_command()`; all_commands() lists them.
#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <vector>

namespace mark::cli {

class Command {
 public:
  Command(std::function<CLI::App*(CLI::App&)> attach, std::function<int()> run)
      : attach_(std::move(attach)), run_(std::move(run)) {}
  void attach(CLI::App& app) { sub_ = attach_(app); }
  bool parsed() const { return sub_ && sub_->parsed(); }
  int run() { return run_(); }

 private:
  std::function<CLI::App*(CLI::App&)> attach_;
  std::function<int()> run_;
  CLI::App* sub_ = nullptr;
};

Command make_preview_command();
Command make_layout_command();
Command make_fonts_command();
Command make_mark_command();
Command make_peen_command();
Command make_gcode_command();
Command make_tool_measure_command();
Command make_gravure_command();
Command make_code_command();
Command make_job_command();
Command make_serial_command();
Command make_log_command();
Command make_store_command();
Command make_devices_command();
Command make_frame_command();
Command make_head_command();
Command make_options_command();
Command make_lmc_command();
Command make_serve_command();

std::vector<Command> all_commands();

}  // namespace mark::cli
