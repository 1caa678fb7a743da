#pragma once
// The embedded serial store: one SQLite file (WAL journal, synchronous=FULL: a commit is on the
// disk when it returns; 64-bit integers). Stations on one machine may share the file; a line
// of several machines shares a PostgreSQL store instead. Reads run in read-only transactions on
// a snapshot, so a long `marker log` never holds up a station's allocation.
#include <memory>
#include <string>

#include "marker/store/store_backend.hpp"

namespace mark {

enum class StoreAccess {
  create,     // create the store when it does not exist (or upgrade an older format)
  existing,   // read and write an existing store
  read_only,  // read an existing store, never write (works on a file this process cannot write)
};

struct SqliteOptions {
  int busy_timeout_ms = 2000;    // the longest wait for another writer's lock
  bool fault_injection = false;  // open through the fault VFS (sqlite_fault_vfs.hpp)
};

// Throws StoreError naming the path: missing (without `create`), damaged, another format.
std::unique_ptr<StoreBackend> open_sqlite_store(const std::string& path, StoreAccess access,
                                                const SqliteOptions& options = {});

}  // namespace mark
