#pragma once
// What was marked, as something other than the device can tell: the quality figures of the mark,
// its pulse figures, each code read back. The caller that made the device passes its evaluator
// in (JobOptions::evaluator) — the simulated scanner that was the device or that sits behind an
// emulated board (marker/job/sim_evaluator.hpp); a camera one day — so the job runner never asks
// what kind of device it drove.
#include "marker/job/job.hpp"

namespace mark {

class MarkEvaluator {
 public:
  virtual ~MarkEvaluator() = default;
  // Before the device's begin_job, the job as compiled: an evaluator whose plant sits behind the
  // device arms it here.
  virtual void begin(const JobSpec& /*spec*/, const CompiledJob& /*job*/) {}
  // After the device's end_job, whatever the outcome: fills result.quality, result.pulses and
  // result.codes as far as it can tell (a stopped job's figures show how far it got).
  virtual void evaluate(const JobSpec& spec, JobResult& result) = 0;
};

}  // namespace mark
