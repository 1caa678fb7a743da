#pragma once
// What the production commands (mark --job, job, serial, log, store) share: which serial store
// and how long to wait for it, the variables set with --set, and who marks (station, job
// digest, clock).
#include <CLI/CLI.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "marker/limits/store_limits.hpp"
#include "marker/store/serial_store.hpp"
#include "marker/store/sqlite_backend.hpp"

namespace mark::cli {

struct StoreArgs {
  std::string store;                       // --store PATH|URL; empty: the station's store
  int wait_ms = kStoreWaitMsDefault;       // --store-wait-ms
  int attempts = kStoreAttemptsDefault;    // --store-attempts (marking)
};

// --store and --store-wait-ms; with `marking` also --store-attempts. Returns the --store option.
CLI::Option* add_store_options(CLI::App& app, StoreArgs& a, bool marking);
// --store, else the station's store (marker/store/store_location.hpp).
std::string store_location(const std::string& store);
// Opens the store and says which on stderr ("marker: store sqlite:/…"), so every production
// command names the store it read or wrote. With `create`, the station's folder is made.
std::unique_ptr<SerialStore> open_production_store(const StoreArgs& a, StoreAccess access,
                                                   StoreSettings settings = {}, bool fault_injection = false);
// "lot=A17" ×N → {lot: A17}; throws InputError for an entry without '=' or an empty name.
std::map<std::string, std::string> parse_sets(const std::vector<std::string>& sets);
// Station name default: the host name.
std::string default_station();
// The context of this process's marks: station, the job file's path and SHA-256.
MarkContext mark_context(const std::string& station, const std::string& job_path,
                         const std::string& job_bytes);

}  // namespace mark::cli
