#include "marker/store/open_store.hpp"

#include "marker/store/postgres_backend.hpp"

namespace mark {

std::unique_ptr<StoreBackend> open_backend(const std::string& location, StoreAccess access,
                                           const StoreOptions& options) {
  if (is_postgres_url(location)) {
    PgOptions pg;
    pg.lock_timeout_ms = options.wait_ms;
    pg.statement_timeout_ms = options.statement_ms;
    return open_postgres_store(location, access, pg);
  }
  SqliteOptions sq;
  sq.busy_timeout_ms = options.wait_ms;
  sq.fault_injection = options.fault_injection;
  return open_sqlite_store(location, access, sq);
}

std::unique_ptr<SerialStore> open_store(const std::string& location, StoreAccess access, StoreSettings settings,
                                        const StoreOptions& options) {
  return std::make_unique<SerialStore>(open_backend(location, access, options), std::move(settings));
}

}  // namespace mark
