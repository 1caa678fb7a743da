#include "marker/store/open_store.hpp"

#include <filesystem>

#include "marker/store/postgres_backend.hpp"

namespace mark {

std::string default_store_path(const std::string& job_path) {
  std::filesystem::path p(job_path);
  p.replace_extension(".serials.sqlite");
  return p.string();
}

bool is_postgres_url(const std::string& location) {
  return location.rfind("postgresql://", 0) == 0 || location.rfind("postgres://", 0) == 0;
}

std::unique_ptr<SerialStore> open_store(const std::string& location, StoreAccess access) {
  if (is_postgres_url(location))
    return std::make_unique<SerialStore>(open_postgres_store(location));
  return std::make_unique<SerialStore>(open_sqlite_store(location, access));
}

}  // namespace mark
