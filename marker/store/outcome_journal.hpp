#pragma once
// The outcome journal: a part's outcome is written here first — one line, flushed to the disk
// (fdatasync), into space reserved ahead (fallocate), so a full disk still takes it — and only
// then to the store. When the store cannot take the outcome (locked, full, its server gone,
// the process killed while it waited), the journal still holds it, and the next start of the
// station replays it into the store: a part marked in full is never logged void for want of a
// store write.
//
// One journal per store (its store_id) and station, in the station's state folder; a lock
// (flock) keeps it to one process. A line is "<checksum> <JSON>"; a crash can only tear the
// last line, which was never acknowledged, and the next open cuts it off.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "marker/store/audit_row.hpp"

namespace mark {

struct JournalEntry {
  std::int64_t mark_id = 0;
  OutcomeRecord outcome;
  // The row it belongs to, to check the store's row is that row before replaying into it.
  std::map<std::string, std::int64_t> serials;
  std::string text;
};

class OutcomeJournal {
 public:
  // Opens (creating folder and file) the journal of (store_id, station) in `dir`, reads what
  // it holds and reserves space. Throws StoreError (io) naming the file: it cannot be created,
  // or another process holds it.
  OutcomeJournal(const std::string& dir, const std::string& store_id, const std::string& station);
  ~OutcomeJournal();
  OutcomeJournal(const OutcomeJournal&) = delete;
  OutcomeJournal& operator=(const OutcomeJournal&) = delete;

  const std::string& path() const { return path_; }
  // Entries written and not yet applied to the store, oldest first.
  std::vector<JournalEntry> pending() const;
  bool empty() const { return pending_.empty(); }
  // Appends `e` durably; throws StoreError (full or io) when the disk refuses it.
  void append(const JournalEntry& e);
  // `mark_id`'s outcome is in the store. Not flushed: replaying an applied entry finds the
  // outcome in the store and skips it. When nothing is pending and the file has grown, it is
  // emptied and its space reserved again.
  void applied(std::int64_t mark_id);

 private:
  void write_line(const std::string& json, bool sync);
  void reserve();

  std::string path_;
  int fd_ = -1;
  std::map<std::int64_t, JournalEntry> pending_;
};

// The journal file of a store and station in `dir`.
std::string journal_path(const std::string& dir, const std::string& store_id, const std::string& station);

}  // namespace mark
