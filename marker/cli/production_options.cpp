#include "marker/cli/production_options.hpp"

#include <unistd.h>

#include "base/error.hpp"
#include "marker/store/digest.hpp"
#include "marker/store/open_store.hpp"

namespace mark::cli {

std::string store_location(const std::string& store, const std::string& job) {
  if (!store.empty()) return store;
  if (!job.empty()) return default_store_path(job);
  throw InputError("no serial store: give --job FILE (its store is the file next to it) or --store PATH|URL");
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
