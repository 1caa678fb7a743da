#pragma once
// `--device` on the command line: which device a job runs on. "sim" (the default) is the
// simulated scanner for the job's head and tick; "lmc", "lmc:SERIAL" and "lmc-capture:FILE" a
// BJJCZ LMC board over USB (or its bytes captured to a file), its lens field the job's field;
// "lmc-emulated[:VARIANT]" the emulated board with the simulated scanner behind it
// (emulated_lmc_device.hpp). With the device comes what can tell how the mark came out: the
// simulated scanner's evaluator (marker/job/sim_evaluator.hpp) — of the device itself, or of the
// scanner behind the emulated board — or none for a real board.
#include <cstdint>
#include <memory>
#include <string>

#include "driver/device.hpp"
#include "driver/sim/plant.hpp"
#include "marker/cli/lmc_options.hpp"
#include "marker/job/job.hpp"
#include "marker/job/sim_evaluator.hpp"

namespace mark::cli {

// Settings that only the simulated scanner has.
struct SimSettings {
  std::uint64_t fault_at = UINT64_MAX;  // --inject fault@N
  bool trace = false;                   // --trace FILE.csv
  double laser_rise_s = 0;              // --laser-rise-us
  Plant plant;                          // --plant: the head as it is, apart from the planner's model
  bool virtual_time = false;            // --virtual-time: the emulated board's clock too
};

struct OpenedDevice {
  std::unique_ptr<Device> device;
  // The simulated scanner's evaluator (pass it as JobOptions::evaluator); null for a real board.
  // Its scanner() holds the dose and trace for --preview, --dose-png and --trace.
  std::unique_ptr<SimEvaluator> simulator;
};

// The device named by `spec` for this job. Throws InputError naming the option and the kinds
// known.
OpenedDevice open_device(const std::string& spec, const JobSpec& job, const SimSettings& sim,
                         const LmcArgs& lmc = {});

}  // namespace mark::cli
