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
  o.plant = sim.plant;
  return o;
}

}  // namespace

OpenedDevice open_device(const std::string& spec, const JobSpec& job, const SimSettings& sim,
                         const LmcArgs& lmc) {
  if (spec == "sim") {
    auto scanner = std::make_unique<SimScanner>(scanner_options(job, sim));
    auto evaluator = std::make_unique<SimEvaluator>(*scanner);
    return {std::move(scanner), std::move(evaluator)};
  }
  if (const auto board = lmc::parse_lmc_spec(spec)) {
    if (board->emulated) {
      // The emulated device begins and ends its scanner's job with the board's, so the
      // evaluator reads the scanner as it would the simulator's own after end_job.
      auto emulated = std::make_unique<EmulatedLmcDevice>(scanner_options(job, sim),
                                                          to_lmc_options(lmc, job.head.field_mm), *board,
                                                          sim.virtual_time);
      auto evaluator = std::make_unique<SimEvaluator>(emulated->scanner());
      return {std::move(emulated), std::move(evaluator)};
    }
    return {lmc::open_lmc(*board, to_lmc_options(lmc, job.head.field_mm)), nullptr};
  }
  throw InputError("--device '" + spec +
                   "' is not a known device (sim: the simulated scanner; lmc, lmc:SERIAL, "
                   "lmc-capture:FILE: a BJJCZ LMC board; lmc-emulated[:VARIANT]: the emulated board "
                   "and the simulated scanner)");
}

}  // namespace mark::cli
