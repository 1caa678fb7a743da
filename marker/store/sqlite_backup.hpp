#pragma once
// `marker store backup FILE`: a copy of an SQLite store taken with SQLite's online backup API
// while stations go on marking (a read snapshot in WAL mode blocks no writer). The copy goes to
// a temporary file beside FILE, is checked (PRAGMA quick_check), flushed to the disk and only
// then renamed over FILE: a backup that fails leaves no file, and a file that exists is whole.
#include <cstdint>
#include <string>

namespace mark {

struct BackupReport {
  std::string target;
  std::int64_t bytes = 0;  // of the copy
  std::int64_t rows = 0;   // audit rows in it
};

// Throws StoreError naming the store or the target.
BackupReport backup_sqlite_store(const std::string& source, const std::string& target);

}  // namespace mark
