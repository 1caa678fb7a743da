#include "marker/store/outcome_journal.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "marker/store/digest.hpp"
#include "marker/store/store_error.hpp"

namespace mark {
namespace {

// Space kept allocated past the end of the file, so appends need no new blocks; renewed when
// less than a quarter is left. An outcome line is 1–4 kB.
constexpr off_t kReserve = 1 << 20;
// Emptied when nothing is pending and it has grown past this.
constexpr off_t kCompactAt = 256 << 10;

std::string checksum(const std::string& json) { return sha256_hex(json).substr(0, 16); }

std::string safe_name(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '-' || c == '_') {
      out += static_cast<char>(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  const int e = errno;
  throw StoreError("outcome journal " + path + ": " + what + ": " + std::strerror(e),
                   e == ENOSPC || e == EDQUOT ? StoreErrorKind::full : StoreErrorKind::io);
}

}  // namespace

std::string journal_path(const std::string& dir, const std::string& store_id, const std::string& station) {
  return (std::filesystem::path(dir) / ("outcomes-" + safe_name(store_id) + "-" + safe_name(station) + ".jsonl"))
      .string();
}

OutcomeJournal::OutcomeJournal(const std::string& dir, const std::string& store_id, const std::string& station)
    : path_(journal_path(dir, store_id, station)) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw StoreError("outcome journal " + path_ + ": cannot create its folder: " + ec.message(), StoreErrorKind::io);
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC, 0600);
  if (fd_ < 0) fail(path_, "cannot open");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw StoreError("outcome journal " + path_ + " is in use by another process (the same station on a copy of "
                     "this store?)",
                     StoreErrorKind::busy);
  }
  // Read it whole: lines are small and a journal is emptied whenever nothing is pending.
  std::string text;
  char buf[65536];
  ::lseek(fd_, 0, SEEK_SET);
  for (ssize_t n; (n = ::read(fd_, buf, sizeof buf)) > 0;) text.append(buf, static_cast<std::size_t>(n));
  // A torn last line (a crash mid-write: never acknowledged) is cut off, so the next append
  // starts a line of its own.
  const std::size_t end = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  if (end != text.size() && ::ftruncate(fd_, static_cast<off_t>(end)) != 0) fail(path_, "cannot cut a torn line");
  std::size_t pos = 0;
  while (pos < end) {
    const std::size_t nl = text.find('\n', pos);
    const std::string line = text.substr(pos, nl - pos);
    pos = nl + 1;
    const std::size_t sp = line.find(' ');
    if (sp == std::string::npos || checksum(line.substr(sp + 1)) != line.substr(0, sp)) continue;
    const nlohmann::json j = nlohmann::json::parse(line.substr(sp + 1), nullptr, false);
    if (j.is_discarded() || !j.is_object()) continue;
    const std::int64_t id = j.value("mark_id", std::int64_t{0});
    if (j.value("kind", "") == "applied") {
      pending_.erase(id);
    } else if (j.value("kind", "") == "outcome") {
      JournalEntry e;
      e.mark_id = id;
      e.outcome.time_utc = j.value("time_utc", "");
      e.outcome.outcome = parse_outcome(j.value("outcome", "")).value_or(Outcome::failed);
      e.outcome.message = j.value("message", "");
      e.outcome.figures = j.value("figures", nlohmann::json::object());
      e.serials = j.value("serials", std::map<std::string, std::int64_t>{});
      e.text = j.value("text", "");
      pending_[id] = std::move(e);
    }
  }
  // The folder entry of a new file is durable too.
  if (const int d = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); d >= 0) {
    ::fsync(d);
    ::close(d);
  }
  if (pending_.empty() && end > static_cast<std::size_t>(kCompactAt)) applied(0);
  reserve();
}

OutcomeJournal::~OutcomeJournal() {
  if (fd_ >= 0) ::close(fd_);
}

std::vector<JournalEntry> OutcomeJournal::pending() const {
  std::vector<JournalEntry> out;
  for (const auto& [id, e] : pending_) out.push_back(e);
  return out;
}

void OutcomeJournal::append(const JournalEntry& e) {
  const nlohmann::json j = {{"kind", "outcome"},        {"mark_id", e.mark_id},
                            {"time_utc", e.outcome.time_utc}, {"outcome", to_string(e.outcome.outcome)},
                            {"message", e.outcome.message},   {"figures", e.outcome.figures},
                            {"serials", e.serials},           {"text", e.text}};
  write_line(j.dump(), true);
  pending_[e.mark_id] = e;
}

void OutcomeJournal::applied(std::int64_t mark_id) {
  if (mark_id) {
    pending_.erase(mark_id);
    write_line(nlohmann::json{{"kind", "applied"}, {"mark_id", mark_id}}.dump(), false);
  }
  struct stat st {};
  if (!pending_.empty() || ::fstat(fd_, &st) != 0 || st.st_size < kCompactAt) return;
  if (::ftruncate(fd_, 0) != 0 || ::fdatasync(fd_) != 0) fail(path_, "cannot empty it");
  reserve();
}

void OutcomeJournal::write_line(const std::string& json, bool sync) {
  const std::string line = checksum(json) + " " + json + "\n";
  const off_t before = ::lseek(fd_, 0, SEEK_END);
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int e = errno;
      // No half line may stay: the next append would run into it.
      if (before >= 0) (void)::ftruncate(fd_, before);
      errno = e;
      fail(path_, "cannot write");
    }
    done += static_cast<std::size_t>(n);
  }
  if (sync && ::fdatasync(fd_) != 0) fail(path_, "cannot flush");
  struct stat st {};
  // Renew the reserve when less than a quarter of it is left past the end.
  if (::fstat(fd_, &st) == 0 && static_cast<off_t>(st.st_blocks) * 512 - st.st_size < kReserve / 4) reserve();
}

void OutcomeJournal::reserve() {
  struct stat st {};
  if (::fstat(fd_, &st) != 0) return;
  // Best effort: a disk too full to reserve on now may still take the small lines later.
  (void)::fallocate(fd_, FALLOC_FL_KEEP_SIZE, 0, st.st_size + kReserve);
}

}  // namespace mark
