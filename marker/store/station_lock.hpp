#pragma once
// One marking process per station name and store file. The lock is a byte-range lock on the
// store file itself (Linux open file description locks, F_OFD_SETLK) at an offset derived from
// the station name, far past SQLite's own lock bytes: the kernel keys it on the file, not on
// the path it was reached by, so a symlink, a hard link or "./x" versus "x" all meet the same
// lock; and it drops the lock when the process dies, however it dies.
//
// Two station names share an offset with a probability of 2^-40 per pair; they then exclude
// each other (never the reverse: one name always meets its own lock).
#include <string>

namespace mark {

class StationLocks {
 public:
  // Opens `path` (the store file) for the locks; throws StoreError naming `name`.
  StationLocks(const std::string& path, const std::string& name);
  // Closing the descriptor releases the locks. The store's SQLite connection must be closed
  // first: closing any descriptor of a file drops the process's POSIX locks on it, SQLite's too.
  ~StationLocks();
  StationLocks(const StationLocks&) = delete;
  StationLocks& operator=(const StationLocks&) = delete;

  // True when this process now holds (or already held) the station's lock.
  bool claim(const std::string& station);

 private:
  int fd_ = -1;
  std::string name_;
};

}  // namespace mark
