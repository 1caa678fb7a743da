#include "marker/cli/device_factory.hpp"

#include "base/error.hpp"
#include "driver/lmc/lmc_open.hpp"
#include "driver/sim/sim_scanner.hpp"

namespace mark::cli {

OpenedDevice open_device(const std::string& spec, const JobSpec& job, const SimSettings& sim,
                         const LmcArgs& lmc) {
  if (spec == "sim") {
    SimScannerOptions o = simulator_options(job);
    o.fault_at = sim.fault_at;
    o.trace = sim.trace;
    o.laser_rise_s = sim.laser_rise_s;
    auto scanner = std::make_unique<SimScanner>(std::move(o));
    auto evaluator = std::make_unique<SimEvaluator>(*scanner);
    return {std::move(scanner), std::move(evaluator)};
  }
  if (const auto board = lmc::parse_lmc_spec(spec))
    return {lmc::open_lmc(*board, to_lmc_options(lmc, job.head.field_mm)), nullptr};
  throw InputError("--device '" + spec +
                   "' is not a known device (sim: the simulated scanner; lmc, lmc:SERIAL, "
                   "lmc-capture:FILE: a BJJCZ LMC board)");
}

}  // namespace mark::cli
