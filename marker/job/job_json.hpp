#pragma once
// A device job's figures as JSON: `marker mark --json`, and each object of a part in
// `marker mark --job --json` and in the audit log. Keys name their units; docs/json.md (or
// docs/job-file.md) lists them.
#include <nlohmann/json.hpp>
#include <optional>

#include "marker/job/job.hpp"

namespace mark {

// Deviation, coverage, dose ratio, overshoot, pulse gap, dose per mm and the class; with the
// pulse figures also `separate_dots` (the pulses' overlap is below 0: rows of dots).
nlohmann::json quality_json(const Quality& q, const std::optional<PulseFigures>& pulses = {});

// outcome, ink marked, counts, times, drain figures, the stop or fault, the device's figures,
// the quality (simulator) and the pulse spacing and overlap (simulator).
nlohmann::json job_result_json(const JobResult& r);

}  // namespace mark
