#pragma once
// A part as JSON: the figures the audit log keeps with its outcome (OutcomeRecord::figures),
// and the line `marker mark --job --json` prints for it (JSON Lines). docs/job-file.md lists
// the keys.
#include <nlohmann/json.hpp>

#include "marker/production/part_run.hpp"

namespace mark {

// device, mark_time_s, samples, quality, pulse figures, stopped_at, and per object (in file
// order) its name, pen, text and job_result_json — or `"outcome": "not_marked"`.
nlohmann::json part_figures(const PartResult& part);

// part_figures plus mark_id, kind (mark / remark), remark_of, text, serials, outcome, message.
nlohmann::json part_line(const PartResult& part);

}  // namespace mark
