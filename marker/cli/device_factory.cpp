#include "marker/cli/device_factory.hpp"

#include "base/error.hpp"
#include "driver/lmc/lmc_open.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "marker/cli/emulated_lmc_device.hpp"

namespace mark::cli {
namespace {

SimScannerOptions scanner_options(const JobSpec& job, const SimSettings& sim) {
  SimScannerOptions o = simulator_options(job);
  o.fault_at = sim.fault_at;
  o.trace = sim.trace;
  o.laser_rise_s = sim.laser_rise_s;
  return o;
}

}  // namespace

std::unique_ptr<Device> open_device(const std::string& spec, const JobSpec& job,
                                    const SimSettings& sim, const LmcArgs& lmc) {
  if (spec == "sim") return std::make_unique<SimScanner>(scanner_options(job, sim));
  if (const auto board = lmc::parse_lmc_spec(spec)) {
    if (board->emulated)
      return std::make_unique<EmulatedLmcDevice>(scanner_options(job, sim), to_lmc_options(lmc, job.head.field_mm),
                                                 *board, sim.virtual_time);
    return lmc::open_lmc(*board, to_lmc_options(lmc, job.head.field_mm));
  }
  throw InputError("--device '" + spec +
                   "' is not a known device (sim: the simulated scanner; lmc, lmc:SERIAL, "
                   "lmc-capture:FILE: a BJJCZ LMC board; lmc-emulated[:VARIANT]: the emulated board "
                   "and the simulated scanner)");
}

SimScanner* simulated_scanner(Device& device) {
  if (auto* sim = dynamic_cast<SimScanner*>(&device)) return sim;
  if (auto* emulated = dynamic_cast<EmulatedLmcDevice*>(&device)) return &emulated->scanner();
  return nullptr;
}

JobResult run_on_device(const JobSpec& spec, CompiledJob job, const JobOptions& options, Device& device) {
  SimScanner* scanner = simulated_scanner(device);
  if (scanner == &device) return run_job_simulated(spec, std::move(job), options, *scanner);
  JobResult r = run_compiled_job(spec, std::move(job), options, device);
  if (scanner) {
    r.quality = simulated_quality(r, *scanner);
    r.codes = verify_codes(spec, r.job, scanner->dose());
    r.pulses = scanner->pulses();
  }
  return r;
}

}  // namespace mark::cli
