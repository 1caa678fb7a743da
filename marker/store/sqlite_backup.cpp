#include "marker/store/sqlite_backup.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "marker/store/sqlite_db.hpp"

namespace mark {
namespace {

void fsync_path(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

void remove_temp(const std::string& temp) {
  std::error_code ec;
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) std::filesystem::remove(temp + suffix, ec);
}

}  // namespace

BackupReport backup_sqlite_store(const std::string& source, const std::string& target) {
  if (!std::filesystem::exists(source))
    throw StoreError("serial store " + source + " does not exist", StoreErrorKind::missing);
  const std::string temp = target + ".tmp-" + std::to_string(::getpid());
  remove_temp(temp);
  BackupReport report;
  report.target = target;
  try {
    SqliteDb src(source, SQLITE_OPEN_READONLY | SQLITE_OPEN_FULLMUTEX);
    src.set_busy_wait(10000, nullptr);
    {
      SqliteDb dest(temp, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX, nullptr, target);
      sqlite3_backup* b = sqlite3_backup_init(dest.get(), "main", src.get(), "main");
      if (!b) dest.fail("backup");
      int rc = SQLITE_OK;
      // All pages in one step: one read snapshot of the store, so the copy is consistent.
      for (int tries = 0; tries < 200; ++tries) {
        rc = sqlite3_backup_step(b, -1);
        if (rc != SQLITE_BUSY && rc != SQLITE_LOCKED) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
      sqlite3_backup_finish(b);
      if (rc != SQLITE_DONE)
        throw StoreError("serial store backup " + target + ": " + sqlite3_errstr(rc), sqlite_error_kind(rc));
      {
        SqliteStmt check(dest, "PRAGMA quick_check");
        if (!check.step() || check.text(0) != "ok")
          throw StoreError("serial store backup " + target + ": the copy does not check (" + check.text(0) + ")",
                           StoreErrorKind::corrupt);
      }
      SqliteStmt rows(dest, "SELECT count(*) FROM marks");
      if (rows.step()) report.rows = rows.i64(0);
    }  // closed (the last connection checkpoints): everything is in the file itself
    fsync_path(temp, O_RDONLY);
    std::error_code ec;
    std::filesystem::rename(temp, target, ec);
    if (ec) throw StoreError("serial store backup " + target + ": cannot rename the copy: " + ec.message(), StoreErrorKind::io);
    fsync_path(std::filesystem::absolute(target).parent_path().string(), O_RDONLY | O_DIRECTORY);
  } catch (...) {
    remove_temp(temp);
    throw;
  }
  remove_temp(temp);  // the -wal / -shm a WAL copy leaves beside its temporary name
  report.bytes = static_cast<std::int64_t>(std::filesystem::file_size(target));
  return report;
}

}  // namespace mark
