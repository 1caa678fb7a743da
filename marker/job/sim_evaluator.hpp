#pragma once
// The simulated scanner as the evaluator of a job (marker/job/mark_evaluator.hpp): the quality
// figures of its lit beam path and dose against the figure's intended strokes (or a prepared
// reference), its pulse figures, every code read back off its dose.
//
// The scanner sits in one of two places:
// - it is the job's device: the runner drives its lifecycle, the figures are read after end_job
//   (SimEvaluator(scanner));
// - it is the plant behind another device — an emulated LMC board that executes its list into
//   the scanner on the board's own clock (plan → list packets → board → scanner). Then the
//   evaluator arms the scanner's job before the device begins (reset, begin_job with the job's
//   lit paths, so its dose raster is sized) and reads it after the device's end_job, each
//   through `access`, which runs them where they cannot race the board's clock:
//
//     SimEvaluator eval = SimEvaluator::behind(scanner, [&](auto& f) { board.inspect(f); });
//
//   The scanner's job stays open after the reading (a stopped board may still put out its last
//   laser-off samples); the next begin() closes it.
#include <functional>
#include <vector>

#include "driver/sim/quality.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "marker/job/mark_evaluator.hpp"

namespace mark {

class SimEvaluator : public MarkEvaluator {
 public:
  using Access = std::function<void(const std::function<void()>&)>;

  // The scanner is the job's device. `reference` (optional, not owned) must be built from the
  // figure of the jobs evaluated (a speed search reuses one).
  explicit SimEvaluator(SimScanner& scanner, const QualityReference* reference = nullptr);
  // The scanner is fed by another device; `access` runs the evaluator's work on the scanner
  // where the feeder is quiet (EmulatedBoard::inspect).
  static SimEvaluator behind(SimScanner& scanner, Access access,
                             const QualityReference* reference = nullptr);

  void begin(const JobSpec& spec, const CompiledJob& job) override;
  void evaluate(const JobSpec& spec, JobResult& result) override;

  SimScanner& scanner() const { return scanner_; }

 private:
  void read(const JobSpec& spec, JobResult& result) const;

  SimScanner& scanner_;
  const QualityReference* reference_;
  Access access_;  // set: behind another device
};

// The simulated scanner for a spec: its head, its pen's tick, lit paths recorded.
SimScannerOptions simulator_options(const JobSpec& spec);
// Each of the job's codes read back off the dose of its mark (in the spec's order).
std::vector<CodeVerification> verify_codes(const JobSpec& spec, const CompiledJob& job, const DoseRaster& dose);
// What the job ran on `scanner` was meant to put down: the scanner's pen and pulses, the spec's
// material and which of the two dose sufficiency is judged against.
MarkIntent mark_intent(const JobSpec& spec, const SimScanner& scanner);
// The quality figures of the job `result` just ran on `scanner`, against its figure's intended
// strokes or `reference`.
Quality simulated_quality(const JobResult& result, const SimScanner& scanner, const MarkIntent& intent,
                          const QualityReference* reference = nullptr);
// run_job on the scanner with a SimEvaluator of it: quality, pulses and codes filled. The
// scanner keeps the dose for a preview.
JobResult run_job_simulated(const JobSpec& spec, const JobOptions& options, SimScanner& scanner,
                            const QualityReference* reference = nullptr);
// The same for a job compiled beforehand for a sample-level device (run_compiled_job).
JobResult run_job_simulated(const JobSpec& spec, CompiledJob job, const JobOptions& options,
                            SimScanner& scanner, const QualityReference* reference = nullptr);

}  // namespace mark
