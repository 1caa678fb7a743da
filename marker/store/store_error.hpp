#pragma once
// A store that cannot be opened, read or written. The message names the store and says what to
// do; the kind lets the store's callers decide without parsing text: a locked store or a lost
// connection is worth another attempt, a damaged one is not.
#include <stdexcept>
#include <string>
#include <string_view>

namespace mark {

enum class StoreErrorKind {
  busy,        // locked by another writer past the wait allowed (SQLite busy, PostgreSQL lock timeout)
  full,        // the disk (or the server's) is full
  io,          // an I/O error reading or writing the store
  connection,  // the server connection was lost (PostgreSQL)
  corrupt,     // the store is damaged (or not a store)
  constraint,  // a key refused a row: a value, a text or an outcome recorded already
  cancelled,   // a wait was cancelled (Ctrl-C)
  missing,     // the store does not exist
  other,
};

std::string_view to_string(StoreErrorKind kind);

class StoreError : public std::runtime_error {
 public:
  explicit StoreError(const std::string& what, StoreErrorKind kind = StoreErrorKind::other)
      : std::runtime_error(what), kind_(kind) {}
  StoreErrorKind kind() const noexcept { return kind_; }
  // Another attempt may succeed: busy, connection.
  bool transient() const noexcept {
    return kind_ == StoreErrorKind::busy || kind_ == StoreErrorKind::connection;
  }

 private:
  StoreErrorKind kind_;
};

}  // namespace mark
