#pragma once
// The shared serial store for a line of stations: PostgreSQL through libpq. The same tables as
// the SQLite store; allocation is one transaction (the counter rows locked in name order,
// UPDATE … RETURNING, the issues and the audit row), committed by the server before the
// station's laser fires.
#include <memory>
#include <string>

#include "marker/store/store_backend.hpp"

namespace mark {

// `url`: a libpq connection URI (postgresql://user@host:port/db, host may be a socket
// directory: postgresql:///db?host=/run/postgresql). Throws StoreError.
std::unique_ptr<StoreBackend> open_postgres_store(const std::string& url);

}  // namespace mark
