#include "marker/cli/commands.hpp"

namespace mark::cli {

std::vector<Command> all_commands() {
  std::vector<Command> c;
  c.push_back(make_preview_command());
  c.push_back(make_layout_command());
  c.push_back(make_fonts_command());
  c.push_back(make_mark_command());
  c.push_back(make_peen_command());
  c.push_back(make_gcode_command());
  c.push_back(make_tool_measure_command());
  c.push_back(make_gravure_command());
  c.push_back(make_code_command());
  c.push_back(make_job_command());
  c.push_back(make_serial_command());
  c.push_back(make_log_command());
  c.push_back(make_store_command());
  c.push_back(make_devices_command());
  c.push_back(make_frame_command());
  c.push_back(make_head_command());
  c.push_back(make_options_command());
  c.push_back(make_lmc_command());
  c.push_back(make_serve_command());
  return c;
}

}  // namespace mark::cli
