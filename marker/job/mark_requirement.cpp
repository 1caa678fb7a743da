#include "marker/job/mark_requirement.hpp"

#include <cstdio>

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
  // The dose ratio is max / median: with most of the strokes unlit the median is 0 and the
  // figure a sentinel (quality.hpp), which says less than the words.
  char dose[64];
  if (q.dose_ratio_max >= 1e9)
    std::snprintf(dose, sizeof dose, "most of the strokes got no dose");
  else
    std::snprintf(dose, sizeof dose, "dose ratio %.2f", q.dose_ratio_max);
  char msg[240];
  std::snprintf(msg, sizeof msg, "quality %s, below %s (max deviation %.1f µm, coverage %.2f %%, %s)",
                std::string(to_string(got)).c_str(), std::string(to_string(wanted)).c_str(), q.max_deviation_um,
                100 * q.coverage, dose);
  return msg;
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
