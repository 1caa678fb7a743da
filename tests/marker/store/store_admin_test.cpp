// The store that runs for months: the station lock follows the file, not the path typed; a
// read-only open reads and writes nothing; a damaged store is refused at the station's start in
// one line; a backup is a whole, checked copy that reads back the same log.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <fstream>

#include "marker/store/sqlite_backup.hpp"
#include "marker/store/store_error.hpp"
#include "store_test_support.hpp"

namespace mark {
namespace {

MarkContext station(const std::string& name) {
  MarkContext c;
  c.station = name;
  c.job = "job.json";
  return c;
}

struct Admin : testing::Test {
  std::filesystem::path dir = test::fresh_store_dir("admin");
  std::string path = (dir / "station.sqlite").string();
  std::map<std::string, CounterSpec> counters{{"sn", test::plain_counter()}};
  void TearDown() override { std::filesystem::remove_all(dir); }
  // A store with `parts` parts marked done.
  void fill(int parts) {
    auto store = open_store(path, StoreAccess::create);
    test::create_counters(*store, counters);
    for (int i = 0; i < parts; ++i) {
      const Allocation a = store->allocate(counters, ShiftTable{}, station("filler"), test::render_sn());
      store->record_outcome(a.mark_id, OutcomeRecord{});
    }
  }
};

TEST_F(Admin, TheStationLockFollowsTheFileNotThePath) {
  fill(0);
  const auto link = dir / "alias.sqlite";
  std::filesystem::create_symlink(path, link);
  auto first = open_store(path, StoreAccess::existing);
  first->start_station(station("line-3"));
  // The same file through a symlink and through a path with "./" and "..": the same lock.
  for (const std::string& other : {link.string(), (dir / "." / ".." / dir.filename() / "station.sqlite").string()}) {
    SCOPED_TRACE(other);
    auto second = open_store(other, StoreAccess::existing);
    try {
      second->start_station(station("line-3"));
      FAIL() << "two processes marked as one station";
    } catch (const StoreError& e) {
      EXPECT_EQ(e.kind(), StoreErrorKind::busy);
      EXPECT_NE(std::string(e.what()).find("station 'line-3' is marking in another process"), std::string::npos)
          << e.what();
    }
    EXPECT_NO_THROW(second->start_station(station("line-4")));
  }
  // Released with the store: the station starts again.
  first.reset();
  EXPECT_NO_THROW(open_store(link.string(), StoreAccess::existing)->start_station(station("line-3")));
}

TEST_F(Admin, AReadOnlyOpenReadsAndWritesNothing) {
  fill(3);
  const auto size = std::filesystem::file_size(path);
  const auto mtime = std::filesystem::last_write_time(path);
  auto store = open_store(path, StoreAccess::read_only);
  std::vector<std::int64_t> values;
  AuditFilter f;
  f.limit = 2;
  store->read_log(f, [&](const AuditRow& r) {
    values.push_back(r.mark.serials.at("sn"));
    return true;
  });
  EXPECT_EQ(values, (std::vector<std::int64_t>{2, 3}));  // the last two, oldest first
  EXPECT_THROW(store->allocate(counters, ShiftTable{}, station("s"), test::render_sn()), StoreError);
  store.reset();
  EXPECT_EQ(std::filesystem::file_size(path), size);
  EXPECT_EQ(std::filesystem::last_write_time(path), mtime);
}

// `log --since` reads from the first part at or after the time (the time index gives its id):
// every later part is read, even when the clock went back between parts and an older time sits
// at a higher id, and none before it.
TEST_F(Admin, SinceReadsEveryPartAtOrAfterTheTimeWhenTheClockWentBack) {
  fill(6);
  {
    // The parts' times as a clock set back twice would write them (ids 2-7; 1 is the counter's
    // creation): rewritten past the append-only trigger, as only a test may.
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    const char* times =
        "DROP TRIGGER marks_no_update; UPDATE marks SET time_utc = CASE id WHEN 2 THEN '2026-03-05T09:00:00.000000Z' "
        "WHEN 3 THEN '2026-03-05T09:05:00.000000Z' WHEN 4 THEN '2026-03-05T09:01:00.000000Z' "
        "WHEN 5 THEN '2026-03-05T09:06:00.000000Z' WHEN 6 THEN '2026-03-05T09:02:00.000000Z' "
        "WHEN 7 THEN '2026-03-05T09:07:00.000000Z' ELSE time_utc END WHERE id BETWEEN 2 AND 7";
    ASSERT_EQ(sqlite3_exec(db, times, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
    sqlite3_close(db);
  }
  auto store = open_store(path, StoreAccess::read_only);
  const auto ids_since = [&](const std::string& since) {
    std::vector<std::int64_t> ids;
    AuditFilter f;
    f.since_utc = since;
    store->read_log(f, [&](const AuditRow& r) {
      ids.push_back(r.id);
      return true;
    });
    return ids;
  };
  EXPECT_EQ(ids_since("2026-03-05T09:05:00.000000Z"), (std::vector<std::int64_t>{3, 5, 7}));
  EXPECT_EQ(ids_since("2026-03-05T09:01:30.000000Z"), (std::vector<std::int64_t>{3, 5, 6, 7}));
  EXPECT_EQ(ids_since("2026-03-05T09:00:00.000000Z"), (std::vector<std::int64_t>{2, 3, 4, 5, 6, 7}));
  EXPECT_TRUE(ids_since("2026-03-05T09:07:00.000001Z").empty());
}

TEST_F(Admin, ADamagedStoreIsRefusedAtTheStationsStart) {
  fill(200);
  {
    // Checkpoint the WAL into the file, then overwrite a page in the middle of it.
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "PRAGMA wal_checkpoint(TRUNCATE)", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  const auto size = std::filesystem::file_size(path);
  ASSERT_GT(size, 8u * 4096u);
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(size / 4096 / 2 * 4096));
    const std::string junk(4096, '\x5a');
    f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
  }
  try {
    auto store = open_store(path, StoreAccess::existing);
    store->start_station(station("s"));
    FAIL() << "a damaged store was accepted";
  } catch (const StoreError& e) {
    EXPECT_EQ(e.kind(), StoreErrorKind::corrupt) << e.what();
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find(path), std::string::npos) << what;
  }
  // `store check` says the same, read-only.
  try {
    EXPECT_FALSE(open_store(path, StoreAccess::read_only)->check(false).empty());
  } catch (const StoreError& e) {
    EXPECT_EQ(e.kind(), StoreErrorKind::corrupt) << e.what();
  }
}

TEST_F(Admin, ABackupIsAWholeCheckedCopy) {
  fill(25);
  // Taken while a station holds the store open and marks on.
  auto live = open_store(path, StoreAccess::existing);
  live->start_station(station("s"));
  const std::string copy = (dir / "backup.sqlite").string();
  const BackupReport r = backup_sqlite_store(path, copy);
  live->allocate(counters, ShiftTable{}, station("s"), test::render_sn());
  EXPECT_EQ(r.target, copy);
  EXPECT_EQ(r.rows, 26);  // the counter's creation and 25 parts
  EXPECT_EQ(static_cast<std::uintmax_t>(r.bytes), std::filesystem::file_size(copy));
  auto back = open_store(copy, StoreAccess::read_only);
  EXPECT_TRUE(back->check(false).empty());
  const std::vector<AuditRow> rows = back->log();
  ASSERT_EQ(rows.size(), 26u);
  EXPECT_EQ(rows.back().mark.serials.at("sn"), 25);
  EXPECT_EQ(test::check_store_consistent(*back, "sn").size(), 25u);
  // A copy that cannot be written leaves nothing behind.
  const std::string nowhere = (dir / "no-such-folder" / "b.sqlite").string();
  EXPECT_THROW(backup_sqlite_store(path, nowhere), StoreError);
  EXPECT_FALSE(std::filesystem::exists(nowhere));
  std::size_t files = 0;
  // Only the copy (with the -wal/-shm its read-only open may add): no temporary file left.
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    files += name.rfind("backup", 0) == 0 && name != "backup.sqlite" && name != "backup.sqlite-wal" &&
             name != "backup.sqlite-shm";
  }
  EXPECT_EQ(files, 0u) << "a temporary file was left";
}

}  // namespace
}  // namespace mark
