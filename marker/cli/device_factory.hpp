#pragma once
// `--device` on the command line: which device a job runs on. "sim" (the default) is the
// simulated scanner for the job's head and tick; "lmc", "lmc:SERIAL" and "lmc-capture:FILE" a
// BJJCZ LMC board over USB (or its bytes captured to a file), its lens field the job's field;
// "lmc-emulated[:VARIANT]" the emulated board with the simulated scanner behind it
// (emulated_lmc_device.hpp).
#include <cstdint>
#include <memory>
#include <string>

#include "driver/device.hpp"
#include "marker/cli/lmc_options.hpp"
#include "marker/job/job.hpp"

namespace mark::cli {

// Settings that only the simulated scanner has.
struct SimSettings {
  std::uint64_t fault_at = UINT64_MAX;  // --inject fault@N
  bool trace = false;                   // --trace FILE.csv
  double laser_rise_s = 0;              // --laser-rise-us
  bool virtual_time = false;            // --virtual-time: the emulated board's clock too
};

// The device named by `spec` for this job. Throws InputError naming the option and the kinds
// known.
std::unique_ptr<Device> open_device(const std::string& spec, const JobSpec& job,
                                    const SimSettings& sim, const LmcArgs& lmc = {});

// The simulated scanner a device marks on: the device itself (sim), the one behind the emulated
// board (lmc-emulated), or none.
SimScanner* simulated_scanner(Device& device);

// Runs the job, compiled for the device's level, on the device; where a simulated scanner marks it, with the quality figures, the
// pulses and every code read back off the simulated part (run_job_simulated's figures).
JobResult run_on_device(const JobSpec& spec, CompiledJob job, const JobOptions& options, Device& device);

}  // namespace mark::cli
