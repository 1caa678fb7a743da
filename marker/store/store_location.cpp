#include "marker/store/store_location.hpp"

#include <cstdlib>
#include <filesystem>

namespace mark {
namespace {

// An absolute path from the environment, or nothing.
std::string absolute_env(const char* name) {
  const char* v = std::getenv(name);
  if (!v || v[0] != '/') return "";
  std::string s(v);
  // systemd gives several folders separated by ':' when a unit names several; ours is the first.
  const std::size_t colon = s.find(':');
  return colon == std::string::npos ? s : s.substr(0, colon);
}

}  // namespace

std::string station_state_dir() {
  if (std::string d = absolute_env("STATE_DIRECTORY"); !d.empty()) return d;
  if (std::string d = absolute_env("XDG_STATE_HOME"); !d.empty()) return d + "/marker";
  if (std::string d = absolute_env("HOME"); !d.empty()) return d + "/.local/state/marker";
  return "/var/lib/marker";
}

std::string default_store_path() { return station_state_dir() + "/serials.sqlite"; }
std::string default_journal_dir() { return station_state_dir() + "/journal"; }

std::string job_side_store_path(const std::string& job_path) {
  std::filesystem::path p(job_path);
  p.replace_extension(".serials.sqlite");
  return p.string();
}

bool is_postgres_url(const std::string& location) {
  return location.rfind("postgresql://", 0) == 0 || location.rfind("postgres://", 0) == 0;
}

}  // namespace mark
