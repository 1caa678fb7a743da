#pragma once
// One code marked alone on the simulated scanner and verified: encode (zint) → marks (square,
// dot or line modules) → plan with the pen → checks (field, speeds) → simulated scanner →
// camera image → reader. What `marker code` runs, and what the tests and the speed and module
// searches repeat.
#include <memory>

#include "driver/head_model.hpp"
#include "driver/sim_scanner.hpp"
#include "marker/codes/code_marks.hpp"
#include "marker/codes/code_spec.hpp"
#include "marker/codes/verify.hpp"
#include "marker/job/simulate_plan.hpp"
#include "marker/plan/plan.hpp"

namespace mark {

struct CodeJob {
  CodeSpec spec;
  CodeLayout layout;
  HeadModel head = head_sl10();
  Pen pen;
  VerifyOptions verify;
};

struct CodeJobResult {
  PlacedCode code;
  Plan plan;
  SimulatedMark mark;
  CodeVerification verification;
  std::unique_ptr<SimScanner> scanner;  // kept for previews and pictures
};

// Throws InputError for bad data or layout, or a plan that leaves the field or the head's limits
// (before anything is marked).
CodeJobResult run_code_job(const CodeJob& job);

// The code, placed and planned (no marking): for previews and benchmarks.
PlacedCode place_encoded(const CodeSpec& spec, const CodeLayout& layout);

}  // namespace mark
