#pragma once
// What the production commands (mark --job, job, serial, log) share: where the serial store
// is, the variables set with --set, and who marks (station, job digest, clock).
#include <map>
#include <string>
#include <vector>

#include "marker/store/serial_store.hpp"

namespace mark::cli {

// --store, else the SQLite file next to --job; throws InputError when neither is given.
std::string store_location(const std::string& store, const std::string& job);
// "lot=A17" ×N → {lot: A17}; throws InputError for an entry without '=' or an empty name.
std::map<std::string, std::string> parse_sets(const std::vector<std::string>& sets);
// Station name default: the host name.
std::string default_station();
// The context of this process's marks: station, the job file's path and SHA-256.
MarkContext mark_context(const std::string& station, const std::string& job_path,
                         const std::string& job_bytes);

}  // namespace mark::cli
