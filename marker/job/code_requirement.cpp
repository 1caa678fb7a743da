#include "marker/job/code_requirement.hpp"

#include "marker/job/sim_evaluator.hpp"

namespace mark {

std::optional<std::string> code_grade_shortfall(const JobSpec& spec, const std::vector<PlacedCode>& codes,
                                                const std::vector<CodeVerification>& verifications, int min_grade) {
  for (std::size_t k = 0; k < verifications.size() && k < codes.size(); ++k)
    if (const auto why = grade_shortfall(verifications[k], min_grade))
      return "code " + std::to_string(k + 1) + " (" + std::string(to_string(spec.codes[k].spec.symbology)) + " " +
             std::to_string(codes[k].matrix.rows) + "x" + std::to_string(codes[k].matrix.cols) + "): " + *why;
  return std::nullopt;
}

namespace {

JobOptions prediction_options() {
  JobOptions predict;
  predict.virtual_time = true;
  predict.realtime = false;
  return predict;
}

SimScannerOptions prediction_scanner(const JobSpec& spec, double laser_rise_s) {
  SimScannerOptions o = simulator_options(spec);
  o.laser_rise_s = laser_rise_s;
  return o;
}

}  // namespace

std::optional<std::string> predicted_code_grade_shortfall(const JobSpec& spec, int min_grade, double laser_rise_s) {
  SimScanner sim(prediction_scanner(spec, laser_rise_s));
  const JobResult r = run_job_simulated(spec, prediction_options(), sim);
  return code_grade_shortfall(spec, r.job.codes, r.codes, min_grade);
}

std::optional<std::string> predicted_code_grade_shortfall(const JobSpec& spec, const CompiledJob& job, int min_grade,
                                                          double laser_rise_s) {
  SimScanner sim(prediction_scanner(spec, laser_rise_s));
  const JobResult r = run_job_simulated(spec, job, prediction_options(), sim);
  return code_grade_shortfall(spec, r.job.codes, r.codes, min_grade);
}

}  // namespace mark
