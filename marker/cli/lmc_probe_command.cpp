// `marker lmc probe [--device lmc|lmc:SERIAL|lmc-emulated[:VARIANT]] [--json] [-o REPORT.json]
//  [--field MM] [--source SOURCE] [--laser-bit N] [--red-bit N] [--polygon-delay-units U]`
// First contact with a board: its serial and version, then lists timed with the laser masked off
// (only the red pointer moves) that settle what docs/lmc.md lists as not verified — the
// polygon delay's unit and scaling, whether a jump waits out the laser-off delay, the packets
// buffered before READY clears, what DelayTime and parameter words cost, how moves round to
// ticks, the jump delay the board held, and how long a job's list takes against the estimate.
// Prints what it concluded (and the options a station should use); --json / -o write the report.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "driver/lmc/lmc_open.hpp"
#include "driver/lmc/probe.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/limits/device_settings.hpp"
#include "marker/limits/head_settings.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/output/output_file.hpp"

namespace mark::cli {
namespace {

struct ProbeArgs {
  // The defaults are the settings tables' (add_setting sets them).
  std::string device;
  std::string output;
  bool json = false;
  double field_mm = 0;
  std::string source;
  int laser_bit = 0, red_bit = 0;
  std::string polygon_unit;
};

nlohmann::ordered_json report_json(const std::string& device, const lmc::ProbeReport& r) {
  nlohmann::ordered_json lists = nlohmann::ordered_json::array();
  for (const lmc::ProbeList& l : r.lists)
    lists.push_back({{"name", l.name}, {"words", l.words}, {"measured_s", l.measured_s}});
  return {
      {"device", device},
      {"link", r.link},
      {"serial", r.identity.serial},
      {"version", r.identity.version},
      {"latency_s", r.latency_s},
      {"held_jump_delay_us", r.held_jump_delay_us},
      {"polygon_delay",
       {{"word", r.polygon_word},
        {"corner_us", r.polygon_corner_us},
        {"straight_us", r.polygon_straight_us},
        {"unit", r.polygon_unit},
        {"scaled_by_angle", r.polygon_scaled ? nlohmann::ordered_json(*r.polygon_scaled) : nlohmann::ordered_json()}}},
      {"jump_after_mark",
       {{"laser_off_delay_us", 2000}, {"wait_us", r.off_delay_wait_us}, {"waits_out_laser_off_delay", r.jump_waits}}},
      {"buffered_packets", r.buffered_packets},
      {"buffered_packets_at_least", r.buffered_capped},
      {"delay_time", {{"extra_us", r.delay_time_extra_us}, {"extra_tick", r.delay_time_extra_tick}}},
      {"parameter_word", {{"time_us", r.parameter_word_us}, {"takes_a_tick", r.parameter_word_tick}}},
      {"move_ticks", {{"exact", r.move_ticks_exact}, {"measured", r.move_ticks_measured}, {"rounding", r.move_rounding}}},
      {"job_list",
       {{"moves", r.list_moves},
        {"estimated_s", r.list_estimated_s},
        {"measured_s", r.list_measured_s},
        {"ratio", r.list_estimated_s > 0 ? r.list_measured_s / r.list_estimated_s : 0}}},
      {"settings", {{"polygon_delay_units", r.polygon_units_option}, {"word_ticks", r.parameter_word_tick}}},
      {"conclusions", r.conclusions},
      {"lists", lists},
  };
}

int run_probe(const ProbeArgs& a) {
  const auto spec = lmc::parse_lmc_spec(a.device);
  if (!spec) throw InputError("--device '" + a.device + "': the probe needs an LMC board (lmc, lmc:SERIAL or lmc-emulated[:VARIANT])");
  if (spec->capture)
    throw InputError("--device '" + a.device + "': a capture file answers nothing; the probe needs a board that does "
                     "(lmc, lmc:SERIAL or lmc-emulated[:VARIANT])");
  if (a.laser_bit == a.red_bit) throw InputError("--laser-bit and --red-bit must differ");
  if (!a.output.empty()) check_output_path("-o", a.output, {".json"});
  lmc::LmcOptions board;
  board.field_mm = a.field_mm;
  board.laser_port_bit = a.laser_bit;
  board.red_pointer_bit = a.red_bit;
  lmc::ProbeOptions o;
  o.field_mm = a.field_mm;
  o.laser_bit = a.laser_bit;
  o.red_bit = a.red_bit;
  o.source = *parse_laser_source(a.source);
  o.polygon_delay_unit = a.polygon_unit == "10us" ? lmc::PolygonDelayUnit::ten_us : lmc::PolygonDelayUnit::signed_us;
  const auto link = lmc::open_lmc_link(*spec, board);
  if (!a.json) std::fprintf(stderr, "probing %s with the laser masked off (red pointer only)\n", link->name().c_str());
  const lmc::ProbeReport r = lmc::probe_board(*link, o, [&](const std::string& line) {
    if (!a.json) std::fprintf(stderr, "%s\n", line.c_str());
  });
  const nlohmann::ordered_json j = report_json(a.device, r);
  if (!a.output.empty()) write_file_whole(a.output, j.dump(2) + "\n");
  if (a.json) {
    std::cout << j.dump() << "\n";
    return 0;
  }
  std::printf("board %s, version %04X %04X %04X, on %s\n", r.identity.serial.c_str(), r.identity.version[0],
              r.identity.version[1], r.identity.version[2], r.link.c_str());
  for (const std::string& line : r.conclusions) std::printf("- %s\n", line.c_str());
  if (!a.output.empty()) std::printf("wrote %s\n", a.output.c_str());
  return 0;
}

}  // namespace

Command make_lmc_command() {
  auto a = std::make_shared<ProbeArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* lmc = app.add_subcommand("lmc", "BJJCZ LMC board tools");
        lmc->require_subcommand(1);
        auto* p = lmc->add_subcommand(
            "probe", "first contact with a board: serial, version, and what it does that the open drivers leave open "
                     "(laser masked off, red pointer only; docs/lmc.md)");
        add_setting(*p, kProbeDevice, a->device);
        p->add_flag("--json", a->json, "print the report as one JSON object (docs/json.md)");
        p->add_option("-o,--output", a->output, "also write the report to this file (.json)");
        add_setting(*p, kField, a->field_mm);
        add_setting(*p, kLaserSource, a->source);
        add_setting(*p, kLaserBit, a->laser_bit);
        add_setting(*p, kRedBit, a->red_bit);
        add_setting(*p, kPolygonDelayUnits, a->polygon_unit);
        return lmc;
      },
      [a] { return run_probe(*a); });
}

}  // namespace mark::cli
