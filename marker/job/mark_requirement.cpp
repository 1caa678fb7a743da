#include "marker/job/mark_requirement.hpp"

#include "marker/job/sim_evaluator.hpp"

namespace mark {
namespace {

std::string why_not_read(const CodeVerification& v, std::size_t k) {
  const std::string code = "code " + std::to_string(k + 1);
  const std::string wrong = " (modules wrong: " + std::to_string(v.modules_wrong) + ")";
  if (!v.decoded) return code + " not decoded by " + (v.decided_by.empty() ? "the readers" : v.decided_by) + wrong;
  return code + " read as \"" + v.decoded_data + "\", not \"" + v.expected_data + "\"" + wrong;
}

std::optional<std::string> quality_shortfall(const Quality& q, QualityClass wanted) {
  const QualityClass got = classify(q);
  if (got >= wanted) return std::nullopt;
  return "quality " + std::string(to_string(got)) + ", below " + std::string(to_string(wanted)) + " (" +
         quality_figures(q) + ")";
}

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

std::optional<std::string> code_grade_shortfall(const JobSpec& spec, const std::vector<PlacedCode>& codes,
                                                const std::vector<CodeVerification>& verifications, int min_grade) {
  for (std::size_t k = 0; k < verifications.size() && k < codes.size(); ++k)
    if (const auto why = grade_shortfall(verifications[k], min_grade))
      return "code " + std::to_string(k + 1) + " (" + std::string(to_string(spec.codes[k].spec.symbology)) + " " +
             std::to_string(codes[k].matrix.rows) + "x" + std::to_string(codes[k].matrix.cols) + "): " + *why;
  return std::nullopt;
}

std::optional<std::string> requirement_shortfall(const JobSpec& spec, const JobResult& marked,
                                                 const MarkRequirement& require) {
  for (std::size_t k = 0; k < marked.codes.size(); ++k)
    if (!marked.codes[k].data_match) return why_not_read(marked.codes[k], k);
  if (require.quality && marked.quality)
    if (auto why = quality_shortfall(*marked.quality, *require.quality)) return why;
  if (require.code_grade > 0) return code_grade_shortfall(spec, marked.job.codes, marked.codes, require.code_grade);
  return std::nullopt;
}

std::optional<std::string> predicted_shortfall(const JobSpec& spec, const CompiledJob& job,
                                               const MarkRequirement& require, double laser_rise_s) {
  SimScanner sim(prediction_scanner(spec, laser_rise_s));
  return requirement_shortfall(spec, run_job_simulated(spec, job, prediction_options(), sim), require);
}

}  // namespace mark
