#pragma once
// A plan marked on the simulated scanner in device time, on the calling thread: locus → laser
// delay line → scanner, block by block, with no line memory and no drain. What the figures of a
// mark depend on (the beam's path, the laser bit, the dose) is the same as through the real-time
// job runner; only the wall-clock pacing is left out, which is what verification and speed
// searches want.
#include <cstdint>
#include <memory>
#include <vector>

#include "driver/sim/sim_scanner.hpp"
#include "marker/job/job.hpp"
#include "marker/plan/plan.hpp"

namespace mark {

struct SimulatedMark {
  std::uint64_t samples = 0;  // handed to the scanner, delay-line tail included
  double mark_time_s = 0;     // device time
};

// Throws DeviceError when the scanner refuses a block (a sample outside its field); the scanner
// has then halted with the laser off.
SimulatedMark simulate_plan(const Plan& plan, SimScanner& scanner);

// The scanner for a plan on a head: the pen's tick, lit paths recorded.
SimScannerOptions simulator_options(const HeadModel& head, const Pen& pen);

struct SimulatedJob {
  CompiledJob job;
  std::unique_ptr<SimScanner> scanner;  // keeps the dose, for pictures and further figures
  SimulatedMark mark;
  std::vector<CodeVerification> codes;  // each code read back off the mark
};

// compile_job, then the plan on a fresh simulated scanner in device time, then every code read
// back. Throws what compile_job throws (before anything is marked).
SimulatedJob simulate_job(const JobSpec& spec);

}  // namespace mark
