#include "marker/cli/device_factory.hpp"

#include "driver/sim_scanner.hpp"
#include "fonts/error.hpp"

namespace mark::cli {

std::unique_ptr<Device> open_device(const std::string& spec, const JobSpec& job,
                                    const SimSettings& sim) {
  if (spec == "sim") {
    SimScannerOptions o = simulator_options(job);
    o.fault_at = sim.fault_at;
    o.trace = sim.trace;
    o.laser_rise_s = sim.laser_rise_s;
    return std::make_unique<SimScanner>(std::move(o));
  }
  throw InputError("--device '" + spec + "' is not a known device (sim: the simulated scanner)");
}

}  // namespace mark::cli
