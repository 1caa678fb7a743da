#include "marker/cli/production_options.hpp"

#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/store/digest.hpp"
#include "marker/store/open_store.hpp"

namespace mark::cli {

CLI::Option* add_store_options(CLI::App& app, StoreArgs& a, bool marking) {
  CLI::Option* store = app.add_option(
      "--store", a.store, "serial store: SQLite file or postgresql://… (default: the station's, " + default_store_path() + ")");
  add_setting(app, kStoreWait, a.wait_ms);
  if (marking) add_setting(app, kStoreAttempts, a.attempts);
  return store;
}

std::string store_location(const std::string& store) { return store.empty() ? default_store_path() : store; }

std::unique_ptr<SerialStore> open_production_store(const StoreArgs& a, StoreAccess access, StoreSettings settings,
                                                   bool fault_injection) {
  const std::string where = store_location(a.store);
  if (access == StoreAccess::create && a.store.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(where).parent_path(), ec);
    if (ec) throw InputError("the station's store folder " + station_state_dir() + ": " + ec.message());
  }
  StoreOptions options;
  options.wait_ms = a.wait_ms;
  options.fault_injection = fault_injection;
  settings.retry.attempts = a.attempts;
  auto store = open_store(where, access, std::move(settings), options);
  std::cerr << "marker: store " << store->describe() << "\n";
  return store;
}

std::map<std::string, std::string> parse_sets(const std::vector<std::string>& sets) {
  std::map<std::string, std::string> values;
  for (const std::string& s : sets) {
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--set '" + s + "': expected NAME=VALUE, e.g. --set lot=A17");
    values[s.substr(0, eq)] = s.substr(eq + 1);
  }
  return values;
}

std::string default_station() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0 || !host[0]) return "station";
  return host;
}

MarkContext mark_context(const std::string& station, const std::string& job_path,
                         const std::string& job_bytes) {
  MarkContext c;
  c.station = station.empty() ? default_station() : station;
  c.job = job_path;
  c.job_sha256 = sha256_hex(job_bytes);
  return c;
}

}  // namespace mark::cli
