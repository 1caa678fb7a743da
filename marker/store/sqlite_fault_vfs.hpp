#pragma once
// An SQLite VFS that passes everything to the default one, except that writes of the files of
// one chosen database can be made to fail — with SQLITE_FULL, as the unix VFS reports a full
// disk (ENOSPC), or SQLITE_IOERR_WRITE. SQLite then goes through its real error path (the
// transaction rolls back, the caller sees the store's own error), which is what a store fault
// test must exercise. Only stores opened for fault injection use it.
#include <string>

namespace mark {

// Registers the VFS once per process and returns its name.
const char* sqlite_fault_vfs();
// From now on every write to `db_path` or its -wal / -journal fails with `sqlite_code`
// (SQLITE_FULL or SQLITE_IOERR_WRITE); 0 ends it. One database at a time.
void sqlite_fail_writes(const std::string& db_path, int sqlite_code);

}  // namespace mark
