#include "marker/job/sim_evaluator.hpp"

#include "marker/codes/verify.hpp"
#include "marker/job/code_photo.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job_run.hpp"
#include "marker/job/simulate_plan.hpp"

namespace mark {

SimEvaluator::SimEvaluator(SimScanner& scanner, const QualityReference* reference)
    : scanner_(scanner), reference_(reference) {}

SimEvaluator SimEvaluator::behind(SimScanner& scanner, Access access, const QualityReference* reference) {
  SimEvaluator e(scanner, reference);
  e.access_ = access ? std::move(access) : Access([](const std::function<void()>& f) { f(); });
  return e;
}

void SimEvaluator::begin(const JobSpec& spec, const CompiledJob& job) {
  if (!access_) return;  // the scanner is the device: the runner begins its job
  // What the scanner needs to size its dose raster: the job's lit paths, its pen's laser.
  const JobHeader header = job_header(spec, job, scanner_.describe());
  access_([&] {
    if (scanner_.status().state == DeviceState::running) scanner_.end_job();
    scanner_.reset();
    scanner_.begin_job(header);
  });
}

void SimEvaluator::evaluate(const JobSpec& spec, JobResult& result) {
  if (access_)
    access_([&] { read(spec, result); });
  else
    read(spec, result);
}

void SimEvaluator::read(const JobSpec& spec, JobResult& result) const {
  result.quality = simulated_quality(result, scanner_, mark_intent(spec, scanner_), reference_);
  result.pulses = scanner_.pulses();
  result.codes = verify_codes(spec, result.job, scanner_.picture_dose());
}

SimScannerOptions simulator_options(const JobSpec& spec) { return simulator_options(spec.head, spec.pen); }

std::vector<CodeVerification> verify_codes(const JobSpec& spec, const CompiledJob& job, const DoseRaster& dose) {
  std::vector<CodeVerification> out;
  for (std::size_t k = 0; k < job.codes.size(); ++k)
    out.push_back(check_code(job.codes[k], spec.codes[k].spec, dose, spec.verify));
  return out;
}

MarkIntent mark_intent(const JobSpec& spec, const SimScanner& scanner) {
  MarkIntent intent = scanner.intent();
  intent.material_dose_s_per_mm = 1 / spec.verify.response.spot_line_speed_mm_s();
  intent.dose_vs_material = spec.verify.dose_vs_material;
  return intent;
}

Quality simulated_quality(const JobResult& result, const SimScanner& scanner, const MarkIntent& intent,
                          const QualityReference* reference) {
  return reference ? reference->evaluate(scanner.lit_paths(), scanner.dose(), intent)
                   : evaluate_quality(intended_polylines(result.job.figure), scanner.lit_paths(),
                                      scanner.dose(), intent);
}

JobResult run_job_simulated(const JobSpec& spec, const JobOptions& options, SimScanner& scanner,
                            const QualityReference* reference) {
  SimEvaluator evaluator(scanner, reference);
  JobOptions o = options;
  o.evaluator = &evaluator;
  return run_job(spec, o, scanner);
}

JobResult run_job_simulated(const JobSpec& spec, CompiledJob job, const JobOptions& options,
                            SimScanner& scanner, const QualityReference* reference) {
  SimEvaluator evaluator(scanner, reference);
  JobOptions o = options;
  o.evaluator = &evaluator;
  return run_compiled_job(spec, std::move(job), o, scanner);
}

}  // namespace mark
