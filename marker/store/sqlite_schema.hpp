#pragma once
// The SQLite store's tables (docs/store.md, "Schema"), their creation, and the upgrade of a
// store of an earlier format, in one write transaction.
#include <string>

#include "marker/store/sqlite_db.hpp"

namespace mark {

// 1: marker-store/1; 2: marker-store/2 (marked texts, data rows, reasons and notes).
struct SqliteFormat {
  int version = 0;
  std::string store_id;
};

// Creates the tables of a new store, or upgrades a marker-store/1 store (the marked texts
// filled from its audit rows), in one IMMEDIATE transaction. Throws StoreError for a store of
// another format.
SqliteFormat create_or_upgrade(const SqliteDb& db);
// Reads the format without writing (read-only opens); both versions are readable.
SqliteFormat read_format(const SqliteDb& db);

}  // namespace mark
