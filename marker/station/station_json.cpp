#include "marker/station/station_json.hpp"

#include "marker/production/part_json.hpp"

namespace mark {

nlohmann::json status_json(const StationStatus& s) {
  nlohmann::json j = {{"state", to_string(s.state)}, {"job", s.job}, {"parts", s.parts},
                      {"outcomes", nlohmann::json::object()}, {"last", nullptr}};
  for (const auto& [outcome, n] : s.outcomes) j["outcomes"][outcome] = n;
  if (s.last) j["last"] = part_line(*s.last);
  if (!s.error.empty()) j["error"] = s.error;
  return j;
}

nlohmann::json event_json(const StationEvent& e) {
  if (e.part) return {{"event", "part"}, {"state", to_string(e.state)}, {"part", part_line(*e.part)}};
  return {{"event", "state"}, {"state", to_string(e.state)}};
}

nlohmann::json preview_json(const std::vector<ObjectText>& texts, const std::map<std::string, std::int64_t>& serials) {
  nlohmann::json j = {{"serials", nlohmann::json::object()}, {"objects", nlohmann::json::array()}};
  std::string text;
  for (const auto& [name, value] : serials) j["serials"][name] = value;
  for (const ObjectText& t : texts) {
    text += (text.empty() ? "" : "\n") + t.text;
    j["objects"].push_back({{"name", t.name}, {"text", t.text}});
  }
  j["text"] = text;
  return j;
}

std::string json_text(const nlohmann::json& value) {
  return value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json error_json(const StationError& e) { return {{"error", e.message}, {"code", e.code}}; }

int http_status(const std::string& code) {
  if (code == "busy" || code == "paused" || code == "aborted") return 409;
  if (code == "refused" || code == "syntax") return 400;
  if (code == "notfound" || code == "unknown") return 404;
  if (code == "toolong") return 413;
  if (code == "rejected") return 422;
  if (code == "error" || code == "failed") return 503;
  return 500;
}

}  // namespace mark
