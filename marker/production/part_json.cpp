#include "marker/production/part_json.hpp"

#include "marker/codes/code_json.hpp"
#include "marker/job/job_json.hpp"

namespace mark {

nlohmann::json part_figures(const PartResult& part) {
  nlohmann::json objects = nlohmann::json::array();
  for (const ObjectRun& o : part.objects) {
    nlohmann::json j = o.started ? job_result_json(o.result) : nlohmann::json{{"outcome", "not_marked"}};
    j["name"] = o.name;
    j["pen"] = o.pen;
    j["text"] = o.text;
    // Each code read back off the simulated part (the device was the simulator).
    if (o.started && !o.result.codes.empty()) {
      j["codes"] = nlohmann::json::array();
      for (std::size_t k = 0; k < o.result.codes.size(); ++k) {
        const PlacedCode& c = o.result.job.codes.at(k);
        j["codes"].push_back(code_to_json(c, c.spec, o.result.codes[k]));
      }
    }
    objects.push_back(std::move(j));
  }
  nlohmann::json j = {{"device", part.device},
                      {"mark_time_s", part.mark_time_s},
                      {"samples", part.samples},
                      {"objects", std::move(objects)}};
  if (part.quality) j["quality"] = quality_json(*part.quality, part.pulses);
  if (part.pulses) {
    j["pulse_spacing_um"] = part.pulses->spacing_max_um;
    j["pulse_overlap_fraction"] = part.pulses->overlap();
  }
  if (part.stopped_object) {
    const ObjectRun& o = part.objects[*part.stopped_object];
    j["stopped_at"] = {{"object", o.name},
                       {"index", *part.stopped_object},
                       {"at", o.started ? o.result.stopped_at : 0}};
  }
  return j;
}

nlohmann::json part_line(const PartResult& part) {
  nlohmann::json j = part_figures(part);
  j["mark_id"] = part.mark_id;
  j["kind"] = part.remark_of ? "remark" : "mark";
  j["remark_of"] = part.remark_of ? nlohmann::json(*part.remark_of) : nlohmann::json();
  j["text"] = part.text();
  j["serials"] = part.serials;
  j["outcome"] = part.outcome_name();
  j["message"] = part.message;
  j["data_row"] = part.data_row ? nlohmann::json(*part.data_row) : nlohmann::json();
  j["note"] = part.note;
  // Where the outcome is: "store", "journal" (replayed into the store at the next start) or
  // "none" (the row is recorded aborted at the station's next start).
  j["recorded"] = part.recorded.stored ? "store" : part.recorded.journaled ? "journal" : "none";
  if (!part.recorded.stored) j["record_error"] = part.record_error.empty() ? part.recorded.error : part.record_error;
  return j;
}

}  // namespace mark
