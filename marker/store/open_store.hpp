#pragma once
// Which store a command uses: an SQLite file, or a PostgreSQL database
// (postgresql://… or postgres://…). Without --store, the station's own (store_location.hpp).
#include <memory>
#include <string>

#include "marker/limits/store_limits.hpp"
#include "marker/store/serial_store.hpp"
#include "marker/store/sqlite_backend.hpp"
#include "marker/store/store_location.hpp"

namespace mark {

struct StoreOptions {
  int wait_ms = kStoreWaitMsDefault;            // SQLite busy wait; PostgreSQL lock_timeout
  int statement_ms = kStoreStatementMsDefault;  // PostgreSQL statement_timeout
  bool fault_injection = false;                 // SQLite: through the fault VFS
};

std::unique_ptr<StoreBackend> open_backend(const std::string& location, StoreAccess access,
                                           const StoreOptions& options = {});
// Throws StoreError naming the store.
std::unique_ptr<SerialStore> open_store(const std::string& location, StoreAccess access,
                                        StoreSettings settings = {}, const StoreOptions& options = {});

}  // namespace mark
