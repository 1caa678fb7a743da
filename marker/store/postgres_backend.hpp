#pragma once
// The shared serial store for a line of stations: PostgreSQL through libpq. The same tables as
// the SQLite store; allocation is one transaction (the counter rows locked in name order,
// UPDATE … RETURNING, the issues and the audit row), committed by the server before the
// station's laser fires. Waits are bounded (lock_timeout, statement_timeout) and cancellable;
// a lost connection is connected again between parts (SerialStore's retries).
#include <memory>
#include <string>

#include "marker/store/pg_options.hpp"
#include "marker/store/sqlite_backend.hpp"
#include "marker/store/store_backend.hpp"

namespace mark {

// `url`: a libpq connection URI (postgresql://user@host:port/db, host may be a socket
// directory: postgresql:///db?host=/run/postgresql). With read_only the schema is neither
// created nor upgraded. Throws StoreError.
std::unique_ptr<StoreBackend> open_postgres_store(const std::string& url, StoreAccess access = StoreAccess::create,
                                                  const PgOptions& options = {});

}  // namespace mark
