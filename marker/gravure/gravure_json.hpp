#pragma once
// The `marker gravure --json` object (every field is listed in docs/gravure.md).
#include <nlohmann/json.hpp>

#include "marker/gravure/gravure_job.hpp"

namespace mark {

nlohmann::json to_json(const GravureJobSpec& spec, const GravureReport& report);
nlohmann::json to_json(const FilterBank& bank);
nlohmann::json to_json(const StylusHeadModel& head);

}  // namespace mark
