#pragma once
// Which store a command uses: --store PATH (SQLite) or --store postgresql://… (or postgres://),
// else the SQLite file next to the job ("bracket.json" → "bracket.serials.sqlite").
#include <memory>
#include <string>

#include "marker/store/serial_store.hpp"
#include "marker/store/sqlite_backend.hpp"

namespace mark {

std::string default_store_path(const std::string& job_path);
bool is_postgres_url(const std::string& location);
// Throws StoreError naming the store.
std::unique_ptr<SerialStore> open_store(const std::string& location, StoreAccess access);

}  // namespace mark
