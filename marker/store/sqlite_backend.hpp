#pragma once
// The embedded serial store: one SQLite file (WAL journal, synchronous=FULL: a commit is on the
// disk when it returns; 64-bit integers). Stations on one machine may share the file; a line
// of several machines shares a PostgreSQL store instead.
#include <memory>
#include <string>

#include "marker/store/store_backend.hpp"

namespace mark {

enum class StoreAccess { create, existing };

// Opens (or, with `create`, creates) the store at `path`. Throws StoreError naming the path.
std::unique_ptr<StoreBackend> open_sqlite_store(const std::string& path, StoreAccess access);

}  // namespace mark
