#pragma once
// The station's replies as JSON (the HTTP interface, docs/station.md; docs/json.md lists every
// key): the same Station calls and the same words as the TCP line protocol's replies
// (station_commands.hpp), in objects instead of `name=value` fields. A part is the object
// `marker mark --job --json` prints for it (part_line).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "marker/station/station.hpp"

namespace mark {

// {"state", "job", "parts", "outcomes": {outcome: n}, "last": part | null, "error"?}
nlohmann::json status_json(const StationStatus& status);

// {"event": "state", "state": S} or {"event": "part", "state": S, "part": part}
nlohmann::json event_json(const StationEvent& event);

// {"serials": {counter: value}, "text": joined with \n, "objects": [{"name", "text"}]}
nlohmann::json preview_json(const std::vector<ObjectText>& texts, const std::map<std::string, std::int64_t>& serials);

// The text of an answer. Bytes that are not UTF-8 (a request's path or value echoed in an error)
// become U+FFFD instead of throwing: an answer is always written.
std::string json_text(const nlohmann::json& value);

// {"error": message, "code": code}
nlohmann::json error_json(const StationError& error);

// The HTTP status that means what the TCP `ERR <code>` means: busy / paused / aborted → 409,
// refused / syntax → 400, notfound / unknown → 404, toolong → 413, rejected → 422,
// error / failed → 503 (the station needs a RESET).
int http_status(const std::string& code);

}  // namespace mark
